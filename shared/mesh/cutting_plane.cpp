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
    if (turn < 0) return "the blade polygon is not convex (it turns back at corner " + std::to_string(k) + ")";
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
  Eigen::Index smallest = 0;
  blade.normal.cwiseAbs().minCoeff(&smallest);
  const Eigen::Vector3d first = blade.normal.cross(Eigen::Vector3d::Unit(smallest));
  const Eigen::Vector3d second = blade.normal.cross(first);
  b = a + first;
  c = a + second;
  normal = (b - a).cross(c - a);
  if (blade.polygon.empty()) return;
  corners_ = blade.polygon;
  double size = 0;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& corner : corners_) {
    size = std::max(size, (corner - corners_.front()).norm());
    centroid += corner / static_cast<double>(corners_.size());
  }
  // Raised by the polygon's size, so that a corner and its raised copy are distinct points.
  for (const Eigen::Vector3d& corner : corners_) raised_.push_back(corner + size * normal.normalized());
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
