#include "shared/simulation/prescribed_traction.hpp"

#include "shared/simulation/surface_traction.hpp"

namespace altfem {

PrescribedTraction::PrescribedTraction(const Scene& scene, double time, double tolerance, ConditionSet released)
    : scene_(scene), time_(time), tolerance_(tolerance), released_(released) {}

std::optional<Eigen::Vector3d> PrescribedTraction::at(const Eigen::Vector3d& point,
                                                      const Eigen::Vector3d& normal) const {
  Eigen::Vector3d traction = Eigen::Vector3d::Zero();
  for (std::size_t index = 0; index < scene_.dirichlet.size(); ++index) {
    const DirichletCondition& condition = scene_.dirichlet[index];
    if (!(released_ >> index & 1u) && condition.region.contains(point, tolerance_)) return std::nullopt;
  }
  SurfacePoints here{point.transpose(), normal.transpose(), Eigen::VectorXd::Ones(1)};
  for (const SurfaceTraction& load : scene_.tractions)
    if (load.region.contains(point, tolerance_))
      traction += load.factor(time_) * surface_forces(load, here, time_).row(0).transpose();
  return traction;
}

}  // namespace altfem
