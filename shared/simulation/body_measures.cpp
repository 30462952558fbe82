#include "shared/simulation/body_measures.hpp"

#include <algorithm>
#include <cmath>

namespace altfem {

namespace {

double relative_change(double before, double after) {
  const double scale = std::max(std::abs(before), std::abs(after));
  return scale > 0 ? std::abs(after - before) / scale : 0.0;
}

}  // namespace

BodyMeasureBasis body_measure_basis(const MethodInstance& method, const Discretization& discretization) {
  BodyMeasureBasis basis;
  // ∫ρ dV = Σ_a c_a · f_a with c the coefficients of the constant field e_x and f the
  // load of a unit acceleration e_x; ∫ρ v_i dV = v · f(e_i).
  for (int i = 0; i < 3; ++i) basis.unit_loads[i] = discretization.body_force(Eigen::Vector3d::Unit(i));
  const Eigen::VectorXd unit_x = method.interpolate([](const Eigen::Vector3d&) { return Eigen::Vector3d::UnitX(); });
  basis.mass = unit_x.dot(basis.unit_loads[0]);
  basis.volume = method.volume();
  return basis;
}

BodyMeasures measure_body(const BodyMeasureBasis& basis, const Discretization& discretization,
                          const TimeIntegrator& integrator, const State& state) {
  BodyMeasures measures;
  measures.mass = basis.mass;
  measures.volume = basis.volume;
  for (int i = 0; i < 3; ++i) measures.momentum[i] = state.velocity.dot(basis.unit_loads[i]);
  measures.energy = integrator.kinetic_energy(state) + discretization.energy(state.displacement);
  return measures;
}

nlohmann::json conservation_json(const BodyMeasures& before, const BodyMeasures& after) {
  nlohmann::json result;
  result["mass_change"] = relative_change(before.mass, after.mass);
  if (before.volume && after.volume) result["volume_change"] = relative_change(*before.volume, *after.volume);
  const double momentum_scale = std::max(before.momentum.norm(), after.momentum.norm());
  result["momentum_change"] = momentum_scale > 0 ? (after.momentum - before.momentum).norm() / momentum_scale : 0.0;
  result["energy_before_j"] = before.energy;
  result["energy_jump_j"] = after.energy - before.energy;
  if (before.energy != 0) result["energy_jump_relative"] = (after.energy - before.energy) / std::abs(before.energy);
  return result;
}

}  // namespace altfem
