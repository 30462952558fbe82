// CSG of analytic shapes and the scale/translate map (analytic_shape.hpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "shared/common/error.hpp"
#include "shared/geometry/analytic_shape.hpp"
#include "shared/geometry/feature_curves.hpp"

namespace altfem {

namespace {

enum class Operation { unite, intersect, subtract };

bool disjoint(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b) { return !a.intersects(b); }

// A convex shape contains a box iff it contains the box's 8 corners.
bool convex_contains(const AnalyticShape& convex, const Eigen::AlignedBox3d& box) {
  if (!convex.is_convex()) return false;
  for (int corner = 0; corner < 8; ++corner)
    if (!convex.contains(box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner)))) return false;
  return true;
}

bool pairwise_disjoint(const std::vector<ShapePointer>& shapes) {
  for (std::size_t i = 0; i < shapes.size(); ++i)
    for (std::size_t j = i + 1; j < shapes.size(); ++j)
      if (!disjoint(shapes[i]->bounding_box(), shapes[j]->bounding_box())) return false;
  return true;
}

class Csg final : public AnalyticShape {
public:
  Csg(Operation operation, std::vector<ShapePointer> children) : operation_(operation), children_(std::move(children)) {
    if (children_.size() < 2) throw InputError("analytic shape: CSG needs at least 2 shapes");
    for (const auto& child : children_)
      if (!child) throw InputError("analytic shape: CSG child is null");
  }

  double level_set(const Eigen::Vector3d& x) const override {
    double value = children_.front()->level_set(x);
    for (std::size_t i = 1; i < children_.size(); ++i) {
      const double child = children_[i]->level_set(x);
      switch (operation_) {
        case Operation::unite: value = std::min(value, child); break;
        case Operation::intersect: value = std::max(value, child); break;
        case Operation::subtract: value = std::max(value, -child); break;
      }
    }
    return value;
  }

  Eigen::AlignedBox3d bounding_box() const override {
    Eigen::AlignedBox3d box = children_.front()->bounding_box();
    if (operation_ == Operation::subtract) return box;
    for (std::size_t i = 1; i < children_.size(); ++i) {
      if (operation_ == Operation::unite) box.extend(children_[i]->bounding_box());
      else box = box.intersection(children_[i]->bounding_box());
    }
    return box;
  }

  double smallest_feature() const override {
    double smallest = children_.front()->smallest_feature();
    for (const auto& child : children_) smallest = std::min(smallest, child->smallest_feature());
    return smallest;
  }

  std::optional<AxisPlanes> axis_planes() const override {
    AxisPlanes planes;
    for (const auto& child : children_) {
      const std::optional<AxisPlanes> own = child->axis_planes();
      if (!own) return std::nullopt;
      for (int axis = 0; axis < 3; ++axis)
        planes[axis].insert(planes[axis].end(), (*own)[axis].begin(), (*own)[axis].end());
    }
    for (auto& coordinates : planes) {
      std::sort(coordinates.begin(), coordinates.end());
      coordinates.erase(std::unique(coordinates.begin(), coordinates.end()), coordinates.end());
    }
    return planes;
  }

  std::vector<Polyline> sharp_edges(double spacing) const override {
    const double tolerance = 1e-9 * bounding_box().diagonal().norm();
    std::vector<Polyline> candidates;
    for (std::size_t i = 0; i < children_.size(); ++i) {
      for (Polyline& line : children_[i]->sharp_edges(spacing)) candidates.push_back(std::move(line));
      const std::vector<PlanarFace> faces = children_[i]->planar_faces();
      for (std::size_t j = 0; j < children_.size(); ++j) {
        // A curve between two children with planar faces lies on both: found from the first's only.
        if (j == i || (j < i && !children_[j]->planar_faces().empty())) continue;
        for (const PlanarFace& face : faces)
          for (Polyline& line : zero_set_on_face(face, *children_[j], spacing)) candidates.push_back(std::move(line));
      }
    }
    std::vector<Polyline> edges;
    for (const Polyline& line : candidates)
      for (Polyline& part : parts_on_surface(line, *this, tolerance)) edges.push_back(std::move(part));
    // Curves found separately meet at the same points up to bisection: Mesh_3 needs
    // them to share those ends exactly.
    snap_ends(edges, 1e-6 * bounding_box().diagonal().norm());
    return edges;
  }

  std::vector<PlanarFace> planar_faces() const override {
    std::vector<PlanarFace> faces;
    for (const auto& child : children_)
      for (const PlanarFace& face : child->planar_faces()) faces.push_back(face);
    return faces;
  }

  // Closed form only when the children are disjoint or nested in a convex child
  // (decided from bounding boxes); anything else is left to the octree.
  std::optional<double> exact_volume() const override {
    std::vector<double> volumes;
    for (const auto& child : children_) {
      const auto volume = child->exact_volume();
      if (!volume) return std::nullopt;
      volumes.push_back(*volume);
    }
    switch (operation_) {
      case Operation::unite: return union_volume(volumes);
      case Operation::intersect: return intersection_volume(volumes);
      case Operation::subtract: return difference_volume(volumes);
    }
    return std::nullopt;
  }

private:
  // The index of a convex child containing every other child, if any.
  std::optional<std::size_t> container() const {
    for (std::size_t i = 0; i < children_.size(); ++i) {
      bool all = true;
      for (std::size_t j = 0; j < children_.size() && all; ++j)
        all = i == j || convex_contains(*children_[i], children_[j]->bounding_box());
      if (all) return i;
    }
    return std::nullopt;
  }

  std::optional<double> union_volume(const std::vector<double>& volumes) const {
    if (pairwise_disjoint(children_)) return std::accumulate(volumes.begin(), volumes.end(), 0.0);
    if (const auto outer = container()) return volumes[*outer];
    return std::nullopt;
  }

  std::optional<double> intersection_volume(const std::vector<double>& volumes) const {
    for (std::size_t i = 0; i < children_.size(); ++i)
      for (std::size_t j = i + 1; j < children_.size(); ++j)
        if (disjoint(children_[i]->bounding_box(), children_[j]->bounding_box())) return 0.0;
    // The intersection is the child that every other (convex) child contains.
    for (std::size_t i = 0; i < children_.size(); ++i) {
      bool inside_all = true;
      for (std::size_t j = 0; j < children_.size() && inside_all; ++j)
        inside_all = i == j || convex_contains(*children_[j], children_[i]->bounding_box());
      if (inside_all) return volumes[i];
    }
    return std::nullopt;
  }

  std::optional<double> difference_volume(const std::vector<double>& volumes) const {
    const AnalyticShape& first = *children_.front();
    std::vector<ShapePointer> removed;
    double volume = volumes.front();
    for (std::size_t i = 1; i < children_.size(); ++i) {
      if (disjoint(first.bounding_box(), children_[i]->bounding_box())) continue;
      if (!convex_contains(first, children_[i]->bounding_box())) return std::nullopt;
      removed.push_back(children_[i]);
      volume -= volumes[i];
    }
    if (!pairwise_disjoint(removed)) return std::nullopt;
    return volume;
  }

  Operation operation_;
  std::vector<ShapePointer> children_;
};

class ScaledTranslated final : public AnalyticShape {
public:
  ScaledTranslated(ShapePointer shape, double scale, const Eigen::Vector3d& translate)
      : shape_(std::move(shape)), scale_(scale), translate_(translate) {
    if (!shape_) throw InputError("analytic shape: cannot scale a null shape");
    if (!std::isfinite(scale) || scale <= 0 || !translate.allFinite())
      throw InputError("analytic shape: scale must be > 0 and translate finite");
  }
  // A distance scales with the map, so the result stays a signed distance.
  double level_set(const Eigen::Vector3d& x) const override {
    return scale_ * shape_->level_set((x - translate_) / scale_);
  }
  Eigen::AlignedBox3d bounding_box() const override {
    const Eigen::AlignedBox3d box = shape_->bounding_box();
    return {scale_ * box.min() + translate_, scale_ * box.max() + translate_};
  }
  std::optional<double> exact_volume() const override {
    const auto volume = shape_->exact_volume();
    if (!volume) return std::nullopt;
    return *volume * scale_ * scale_ * scale_;
  }
  bool is_convex() const override { return shape_->is_convex(); }
  double smallest_feature() const override { return scale_ * shape_->smallest_feature(); }
  std::optional<AxisPlanes> axis_planes() const override {
    std::optional<AxisPlanes> planes = shape_->axis_planes();
    if (planes)
      for (int axis = 0; axis < 3; ++axis)
        for (double& coordinate : (*planes)[axis]) coordinate = scale_ * coordinate + translate_[axis];
    return planes;
  }
  std::vector<Polyline> sharp_edges(double spacing) const override {
    std::vector<Polyline> edges = shape_->sharp_edges(spacing / scale_);
    for (Polyline& line : edges)
      for (Eigen::Vector3d& point : line) point = scale_ * point + translate_;
    return edges;
  }
  std::vector<PlanarFace> planar_faces() const override {
    std::vector<PlanarFace> faces = shape_->planar_faces();
    for (PlanarFace& face : faces) face = {scale_ * face.origin + translate_, scale_ * face.u, scale_ * face.v};
    return faces;
  }

private:
  ShapePointer shape_;
  double scale_;
  Eigen::Vector3d translate_;
};

}  // namespace

ShapePointer make_union(std::vector<ShapePointer> children) {
  return std::make_shared<Csg>(Operation::unite, std::move(children));
}

ShapePointer make_intersection(std::vector<ShapePointer> children) {
  return std::make_shared<Csg>(Operation::intersect, std::move(children));
}

ShapePointer make_difference(std::vector<ShapePointer> children) {
  return std::make_shared<Csg>(Operation::subtract, std::move(children));
}

ShapePointer make_scaled_translated(ShapePointer shape, double scale, const Eigen::Vector3d& translate) {
  return std::make_shared<ScaledTranslated>(std::move(shape), scale, translate);
}

}  // namespace altfem
