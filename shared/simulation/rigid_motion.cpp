#include "shared/simulation/rigid_motion.hpp"

namespace altfem {

Eigen::Vector3d centre_of_mass(const MethodInstance& method) {
  const Discretization& discretization = method.discretization();
  const Eigen::VectorXd position = method.interpolate([](const Eigen::Vector3d& x) { return x; });
  const Eigen::VectorXd ones =
      method.interpolate([](const Eigen::Vector3d&) { return Eigen::Vector3d::Ones().eval(); });
  Eigen::Vector3d centre;
  for (int i = 0; i < 3; ++i) {
    const Eigen::VectorXd load = discretization.body_force(Eigen::Vector3d::Unit(i));
    centre[i] = position.dot(load) / ones.dot(load);
  }
  return centre;
}

Eigen::MatrixXd rigid_body_modes(const MethodInstance& method) {
  Eigen::MatrixXd modes(method.discretization().dof_count(), 6);
  for (int axis = 0; axis < 3; ++axis) {
    const Eigen::Vector3d direction = Eigen::Vector3d::Unit(axis);
    modes.col(axis) = method.interpolate([&](const Eigen::Vector3d&) { return direction; });
    modes.col(3 + axis) = method.interpolate([&](const Eigen::Vector3d& x) { return direction.cross(x).eval(); });
  }
  return modes;
}

Eigen::VectorXd initial_velocity(const MethodInstance& method, const InitialConditions& initial) {
  const bool rotating = initial.angular_velocity.squaredNorm() > 0;
  const Eigen::Vector3d centre = rotating && !initial.centre ? centre_of_mass(method) : Eigen::Vector3d::Zero().eval();
  return method.interpolate([&](const Eigen::Vector3d& x) { return initial.velocity_at(x, centre); });
}

}  // namespace altfem
