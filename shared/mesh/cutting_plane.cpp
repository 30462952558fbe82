#include "shared/mesh/cutting_plane.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "shared/geometry/exact_orientation.hpp"

namespace altfem {

CuttingPlane polygon_blade(std::vector<Eigen::Vector3d> corners) {
  CuttingPlane blade;
  // Newell's normal: exact for a planar polygon, an average plane otherwise.
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < corners.size(); ++k) normal += corners[k].cross(corners[(k + 1) % corners.size()]);
  if (!corners.empty()) blade.point = corners.front();
  blade.normal = normal;
  blade.polygon = std::move(corners);
  return blade;
}

CuttingPlane swept_blade(const CuttingPlane& blade, const Eigen::Vector3d& translation) {
  // Andrew's monotone chain in the plane's coordinates (Eigen and a dozen corners: CGAL's
  // convex_hull_2 would need a projection traits class for an arbitrary plane).
  const Eigen::Vector3d normal = blade.normal.normalized();
  Eigen::Index smallest = 0;
  normal.cwiseAbs().minCoeff(&smallest);
  const Eigen::Vector3d first = normal.cross(Eigen::Vector3d::Unit(smallest)).normalized();
  const Eigen::Vector3d second = normal.cross(first);
  std::vector<Eigen::Vector3d> points = blade.polygon;
  for (const Eigen::Vector3d& corner : blade.polygon) points.push_back(corner + translation);
  const auto coordinates = [&](const Eigen::Vector3d& x) {
    return Eigen::Vector2d((x - blade.point).dot(first), (x - blade.point).dot(second));
  };
  std::sort(points.begin(), points.end(), [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    const Eigen::Vector2d u = coordinates(a), v = coordinates(b);
    return u.x() < v.x() || (u.x() == v.x() && u.y() < v.y());
  });
  double size = 0;
  for (const Eigen::Vector3d& point : points) size = std::max(size, (point - points.front()).norm());
  // Positive when a → b → c turns counter-clockwise about the normal, by more than round-off.
  const auto turns_left = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    const Eigen::Vector2d u = coordinates(b) - coordinates(a), v = coordinates(c) - coordinates(a);
    return u.x() * v.y() - u.y() * v.x() > 1e-12 * size * size;
  };
  std::vector<Eigen::Vector3d> hull;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t start = hull.size();
    for (const Eigen::Vector3d& point : points) {
      while (hull.size() >= start + 2 && !turns_left(hull[hull.size() - 2], hull.back(), point)) hull.pop_back();
      hull.push_back(point);
    }
    hull.pop_back();  // the chain's last point starts the other chain
    std::reverse(points.begin(), points.end());
  }
  CuttingPlane swept = blade;
  swept.polygon = std::move(hull);
  return swept;
}

std::string blade_polygon_problem(const CuttingPlane& blade) {
  const std::vector<Eigen::Vector3d>& corners = blade.polygon;
  if (corners.empty()) return "";
  if (corners.size() < 3) return "a blade polygon needs at least 3 corners, got " + std::to_string(corners.size());
  for (const Eigen::Vector3d& corner : corners)
    if (!corner.allFinite()) return "a blade polygon's corners must be finite";
  if (!(blade.normal.squaredNorm() > 0) || !blade.normal.allFinite())
    return "a blade polygon must enclose an area (its corners are collinear, or it crosses itself)";
  double size = 0;
  for (const Eigen::Vector3d& corner : corners) size = std::max(size, (corner - corners.front()).norm());
  const Eigen::Vector3d unit = blade.normal.normalized();
  for (std::size_t k = 0; k < corners.size(); ++k) {
    if (std::abs((corners[k] - blade.point).dot(unit)) > 1e-9 * size)
      return "corner " + std::to_string(k) + " of the blade polygon is off the plane of the others";
    if ((corners[(k + 1) % corners.size()] - corners[k]).norm() <= 1e-12 * size)
      return "corners " + std::to_string(k) + " and " + std::to_string((k + 1) % corners.size()) +
             " of the blade polygon coincide";
  }
  // Convex: every turn the same way round the normal, and one winding only.
  double winding = 0;
  for (std::size_t k = 0; k < corners.size(); ++k) {
    const Eigen::Vector3d& previous = corners[(k + corners.size() - 1) % corners.size()];
    const Eigen::Vector3d& next = corners[(k + 1) % corners.size()];
    const double turn = (corners[k] - previous).cross(next - corners[k]).dot(unit);
    // A corner where the polygon runs straight on may turn either way by round-off.
    if (turn < -1e-12 * (corners[k] - previous).norm() * (next - corners[k]).norm())
      return "the blade polygon is not convex (it turns back at corner " + std::to_string(k) + ")";
    winding += std::atan2(turn, (corners[k] - previous).dot(next - corners[k]));
  }
  if (winding > 2 * M_PI * (1 + 1e-9)) return "the blade polygon is not convex (it winds around more than once)";
  return "";
}

ExactBlade::ExactBlade(const CuttingPlane& blade) : a(blade.point) {
  if (!(blade.normal.squaredNorm() > 0) || !blade.normal.allFinite())
    throw std::invalid_argument("cut: the plane's normal must be finite and non-zero");
  if (const std::string problem = blade_polygon_problem(blade); !problem.empty())
    throw std::invalid_argument("cut: " + problem);
  // The plane's points and the side planes' raised points from the normal's line only, not
  // its sense: two blades through the same point with opposite normals (the triangles of a
  // flat part of a surface blade, which share them) then decide with the same points, each
  // side exactly the other's negated, and where they share an edge a point covered by
  // neither is impossible even off the plane by a rounding (a face whose centroid lay on
  // such an edge was separated by neither, leaving a cell whole across the blade).
  Eigen::Index largest = 0, smallest = 0;
  blade.normal.cwiseAbs().maxCoeff(&largest);
  blade.normal.cwiseAbs().minCoeff(&smallest);
  const Eigen::Vector3d up = (blade.normal(largest) > 0 ? 1.0 : -1.0) * blade.normal.normalized();
  const Eigen::Vector3d first = up.cross(Eigen::Vector3d::Unit(smallest));
  const Eigen::Vector3d second = up.cross(first);
  b = a + first;
  c = a + second;
  if (blade.normal(largest) < 0) std::swap(b, c);  // (b − a) × (c − a) along the blade's normal
  normal = (b - a).cross(c - a);
  if (blade.polygon.empty()) return;
  corners_ = blade.polygon;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < corners_.size(); ++k) {
    centroid += corners_[k] / static_cast<double>(corners_.size());
    // Edge k's side plane through it and its lesser end raised by its length (distinct
    // points), whichever way round a polygon runs along it.
    const auto [low, high] =
        std::minmax(corners_[k], corners_[(k + 1) % corners_.size()], [](const auto& p, const auto& q) {
          return std::lexicographical_compare(p.data(), p.data() + 3, q.data(), q.data() + 3);
        });
    raised_.push_back(low + (high - low).norm() * up);
  }
  inside_sign_ = orientation_sign(corners_[0], corners_[1], raised_[0], centroid);
  if (inside_sign_ == 0) throw std::invalid_argument("cut: the blade polygon has no area");
}

int ExactBlade::side(const Eigen::Vector3d& point) const { return orientation_sign(a, b, c, point); }

bool ExactBlade::covers(const Eigen::Vector3d& point) const {
  for (std::size_t k = 0; k < corners_.size(); ++k)
    if (orientation_sign(corners_[k], corners_[(k + 1) % corners_.size()], raised_[k], point) * inside_sign_ < 0)
      return false;
  return true;
}

bool ExactBlade::covers_crossing(const Eigen::Vector3d& p, const Eigen::Vector3d& q) const {
  for (std::size_t k = 0; k < corners_.size(); ++k)
    if (crossing_orientation_sign(a, b, c, p, q, corners_[k], corners_[(k + 1) % corners_.size()], raised_[k]) *
            inside_sign_ <
        0)
      return false;
  return true;
}

}  // namespace altfem
