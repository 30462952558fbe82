#include "shared/geometry/analytic_shape.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "shared/common/error.hpp"

namespace altfem {

namespace {

void require(bool condition, const std::string& what) {
  if (!condition) throw InputError("analytic shape: " + what);
}

// The segment a → b sampled at most `spacing` apart (both ends included).
Polyline sampled_segment(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double spacing) {
  const int pieces = std::max(1, static_cast<int>(std::ceil((b - a).norm() / spacing)));
  Polyline line;
  for (int i = 0; i <= pieces; ++i) line.push_back(a + (b - a) * (static_cast<double>(i) / pieces));
  return line;
}

// A closed circle of radius r about `centre` in the plane orthogonal to the unit `axis`.
Polyline sampled_circle(const Eigen::Vector3d& centre, const Eigen::Vector3d& axis, double radius, double spacing) {
  const int pieces = std::max(16, static_cast<int>(std::ceil(2 * std::numbers::pi * radius / spacing)));
  const Eigen::Vector3d u = axis.unitOrthogonal(), v = axis.cross(u);
  Polyline circle;
  for (int i = 0; i < pieces; ++i) {
    const double angle = 2 * std::numbers::pi * i / pieces;
    circle.push_back(centre + radius * (std::cos(angle) * u + std::sin(angle) * v));
  }
  circle.push_back(circle.front());
  return circle;
}

// Exact signed distance to an axis-aligned box (the classic construction: the
// outside part is the distance to the clamped point, the inside part the distance
// to the nearest face).
class Box final : public AnalyticShape {
public:
  Box(const Eigen::Vector3d& min, const Eigen::Vector3d& max) : box_(min, max) {
    require(min.allFinite() && max.allFinite() && (min.array() < max.array()).all(),
            "box needs finite min < max in every component");
  }
  double level_set(const Eigen::Vector3d& x) const override {
    const Eigen::Vector3d q = (x - box_.center()).cwiseAbs() - 0.5 * box_.sizes();
    return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
  }
  Eigen::AlignedBox3d bounding_box() const override { return box_; }
  std::optional<double> exact_volume() const override { return box_.volume(); }
  bool is_convex() const override { return true; }
  double smallest_feature() const override { return box_.sizes().minCoeff(); }
  std::optional<AxisPlanes> axis_planes() const override {
    AxisPlanes planes;
    for (int axis = 0; axis < 3; ++axis) planes[axis] = {box_.min()[axis], box_.max()[axis]};
    return planes;
  }
  std::vector<PlanarFace> planar_faces() const override {
    std::vector<PlanarFace> faces;
    const Eigen::Vector3d size = box_.sizes();
    for (int axis = 0; axis < 3; ++axis) {
      const Eigen::Vector3d u = size[(axis + 1) % 3] * Eigen::Vector3d::Unit((axis + 1) % 3);
      const Eigen::Vector3d v = size[(axis + 2) % 3] * Eigen::Vector3d::Unit((axis + 2) % 3);
      faces.push_back({box_.min(), u, v});
      faces.push_back({box_.min() + size[axis] * Eigen::Vector3d::Unit(axis), u, v});
    }
    return faces;
  }
  std::vector<Polyline> sharp_edges(double spacing) const override {
    std::vector<Polyline> edges;
    // The 12 edges join corners that differ in one bit (x = 1, y = 2, z = 4).
    for (int corner = 0; corner < 8; ++corner)
      for (int bit : {1, 2, 4})
        if (!(corner & bit))
          edges.push_back(sampled_segment(corner_point(corner), corner_point(corner | bit), spacing));
    return edges;
  }

private:
  Eigen::Vector3d corner_point(int bits) const {
    return {bits & 1 ? box_.max().x() : box_.min().x(), bits & 2 ? box_.max().y() : box_.min().y(),
            bits & 4 ? box_.max().z() : box_.min().z()};
  }

  Eigen::AlignedBox3d box_;
};

class Sphere final : public AnalyticShape {
public:
  Sphere(const Eigen::Vector3d& centre, double radius) : centre_(centre), radius_(radius) {
    require(centre.allFinite() && std::isfinite(radius) && radius > 0, "sphere needs a finite radius > 0");
  }
  double level_set(const Eigen::Vector3d& x) const override { return (x - centre_).norm() - radius_; }
  Eigen::AlignedBox3d bounding_box() const override { return {centre_.array() - radius_, centre_.array() + radius_}; }
  std::optional<double> exact_volume() const override {
    return 4.0 / 3.0 * std::numbers::pi * radius_ * radius_ * radius_;
  }
  bool is_convex() const override { return true; }
  double smallest_feature() const override { return radius_; }

private:
  Eigen::Vector3d centre_;
  double radius_;
};

// A solid of revolution is the revolved 2D cross-section in the (ρ, z) meridian
// half-plane, so the exact 3D signed distance is the 2D signed distance of (ρ, z) to
// that section: the rectangle [r0, R] × [0, H] (a hollow cylinder) or, for a solid
// cylinder, [−R, R] × [0, H] (mirrored so the axis is not a boundary).
class Cylinder final : public AnalyticShape {
public:
  Cylinder(const Eigen::Vector3d& base, const Eigen::Vector3d& axis, double height, double radius, double inner_radius)
      : base_(base), height_(height), radius_(radius), inner_radius_(inner_radius) {
    require(base.allFinite() && axis.allFinite() && axis.norm() > 0, "cylinder needs a finite non-zero axis");
    require(std::isfinite(height) && height > 0, "cylinder needs a height > 0");
    require(std::isfinite(radius) && radius > 0, "cylinder needs a radius > 0");
    require(inner_radius >= 0 && inner_radius < radius, "cylinder needs 0 <= inner_radius < radius");
    axis_ = axis.normalized();
  }
  double level_set(const Eigen::Vector3d& x) const override {
    const Eigen::Vector3d d = x - base_;
    const double z = d.dot(axis_);
    const double rho = (d - z * axis_).norm();
    const double centre_r = inner_radius_ > 0 ? 0.5 * (radius_ + inner_radius_) : 0.0;
    const double half_r = inner_radius_ > 0 ? 0.5 * (radius_ - inner_radius_) : radius_;
    const Eigen::Vector2d q(std::abs(rho - centre_r) - half_r, std::abs(z - 0.5 * height_) - 0.5 * height_);
    return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
  }
  Eigen::AlignedBox3d bounding_box() const override {
    // A disc of radius R with unit normal a reaches R·sqrt(1 − a_i²) along axis i.
    const Eigen::Vector3d reach = radius_ * (1.0 - axis_.array().square()).max(0.0).sqrt();
    const Eigen::Vector3d top = base_ + height_ * axis_;
    return {base_.cwiseMin(top) - reach, base_.cwiseMax(top) + reach};
  }
  std::optional<double> exact_volume() const override {
    return std::numbers::pi * (radius_ * radius_ - inner_radius_ * inner_radius_) * height_;
  }
  bool is_convex() const override { return inner_radius_ == 0.0; }
  double smallest_feature() const override {
    return std::min({height_, radius_, inner_radius_ > 0 ? radius_ - inner_radius_ : radius_});
  }
  std::vector<Polyline> sharp_edges(double spacing) const override {
    std::vector<Polyline> rims;
    for (double z : {0.0, height_}) {
      rims.push_back(sampled_circle(base_ + z * axis_, axis_, radius_, spacing));
      if (inner_radius_ > 0) rims.push_back(sampled_circle(base_ + z * axis_, axis_, inner_radius_, spacing));
    }
    return rims;
  }

private:
  Eigen::Vector3d base_, axis_;
  double height_, radius_, inner_radius_;
};

// Volume of the shape inside one cell of the octree (centre, half-sizes), refined
// `depth` more times where the level set cannot decide the cell.
double cell_volume(const AnalyticShape& shape, const Eigen::Vector3d& centre, const Eigen::Vector3d& half, int depth) {
  const double phi = shape.level_set(centre);
  const double reach = half.norm();
  const double volume = 8.0 * half.prod();
  // |φ| is at most the distance to the surface (1-Lipschitz), so a ball of radius
  // |φ| around the centre lies on one side.
  if (phi <= -reach) return volume;
  if (phi >= reach) return 0.0;
  if (depth == 0) {
    // Treat the surface as the plane φ + ∇φ·(x − centre) = 0 (∇φ by central
    // differences) and take the inside fraction as linear in the plane's offset
    // across the cell's half-width w = Σ|n_i| h_i along the unit normal n: exact
    // when the plane passes through the centre or touches a corner.
    Eigen::Vector3d gradient;
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3d step = 0.5 * half[i] * Eigen::Vector3d::Unit(i);
      gradient[i] = (shape.level_set(centre + step) - shape.level_set(centre - step)) / half[i];
    }
    const double slope = gradient.norm();
    const double width = slope > 0 ? gradient.cwiseAbs().dot(half) / slope : half.norm();
    const double distance = slope > 0 ? phi / slope : phi;
    return volume * std::clamp(0.5 - distance / (2.0 * width), 0.0, 1.0);
  }
  double sum = 0.0;
  const Eigen::Vector3d quarter = 0.5 * half;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d sign((corner & 1) ? 1.0 : -1.0, (corner & 2) ? 1.0 : -1.0, (corner & 4) ? 1.0 : -1.0);
    sum += cell_volume(shape, centre + sign.cwiseProduct(quarter), quarter, depth - 1);
  }
  return sum;
}

}  // namespace

double AnalyticShape::volume() const {
  if (const auto exact = exact_volume()) return *exact;
  return integrate_volume(*this, volume_tolerance);
}

ShapePointer make_box(const Eigen::Vector3d& min, const Eigen::Vector3d& max) {
  return std::make_shared<Box>(min, max);
}

ShapePointer make_sphere(const Eigen::Vector3d& centre, double radius) {
  return std::make_shared<Sphere>(centre, radius);
}

ShapePointer make_cylinder(const Eigen::Vector3d& base, const Eigen::Vector3d& axis, double height, double radius,
                           double inner_radius) {
  return std::make_shared<Cylinder>(base, axis, height, radius, inner_radius);
}

double integrate_volume(const AnalyticShape& shape, double relative_tolerance) {
  const Eigen::AlignedBox3d box = shape.bounding_box();
  if (box.isEmpty()) return 0.0;
  // Slightly enlarged so that surface points on the box's faces are inside cells.
  const Eigen::Vector3d half = 0.5 * box.sizes() * (1.0 + 1e-6);
  constexpr int first_depth = 4, last_depth = 10;
  // Two agreements in a row: one can be a coincidence of the leaf estimate.
  double previous = cell_volume(shape, box.center(), half, first_depth);
  int agreements = 0;
  for (int depth = first_depth + 1; depth <= last_depth; ++depth) {
    const double current = cell_volume(shape, box.center(), half, depth);
    agreements = std::abs(current - previous) <= relative_tolerance * std::abs(current) ? agreements + 1 : 0;
    if (agreements == 2) return current;
    previous = current;
  }
  throw NumericalError("analytic shape: octree volume did not reach relative tolerance " +
                       std::to_string(relative_tolerance) + " within " + std::to_string(last_depth) + " levels");
}

}  // namespace altfem
