// Evaluating what a scene prescribes: which points a region selects, the
// displacement a motion imposes, the initial velocity field.
#include <Eigen/Geometry>
#include <algorithm>
#include <limits>

#include "shared/scene/scene.hpp"

namespace altfem {

bool RegionSelector::contains(const Eigen::Vector3d& x, double tolerance) const {
  switch (kind) {
    case RegionKind::box:
      return (x.array() >= box.min().array() - tolerance).all() && (x.array() <= box.max().array() + tolerance).all();
    case RegionKind::half_space: return (x - point).dot(normal) <= tolerance;
    case RegionKind::sphere: return (x - centre).norm() <= radius + tolerance;
  }
  return false;
}

Eigen::AlignedBox3d RegionSelector::bounds() const {
  switch (kind) {
    case RegionKind::box: return box;
    case RegionKind::sphere: return {centre.array() - radius, centre.array() + radius};
    case RegionKind::half_space: break;
  }
  const double infinity = std::numeric_limits<double>::infinity();
  return {Eigen::Vector3d::Constant(-infinity), Eigen::Vector3d::Constant(infinity)};
}

double region_tolerance(const Eigen::AlignedBox3d& geometry_bounds) { return 1e-6 * geometry_bounds.diagonal().norm(); }

Eigen::Vector3d Motion::displacement(const Eigen::Vector3d& rest_position, double time) const {
  switch (kind) {
    case MotionKind::fixed: return Eigen::Vector3d::Zero();
    case MotionKind::translate:
      if (duration > 0) return std::clamp(time / duration, 0.0, 1.0) * total_displacement;
      return time * velocity;
    case MotionKind::rotate: {
      const Eigen::AngleAxisd rotation(angular_velocity * time, axis);
      return rotation * (rest_position - centre) + centre - rest_position;
    }
    case MotionKind::field: return field(rest_position, time);
  }
  return Eigen::Vector3d::Zero();
}

Eigen::Vector3d InitialConditions::velocity_at(const Eigen::Vector3d& x, const Eigen::Vector3d& centre_of_mass) const {
  return velocity + angular_velocity.cross(x - centre.value_or(centre_of_mass));
}

}  // namespace altfem
