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

BodyMeasures measure_body(const MethodInstance& method, const Discretization& discretization,
                          const TimeIntegrator& integrator, const State& state) {
  BodyMeasures measures;
  // ∫ρ dV = Σ_a c_a · f_a with c the coefficients of the constant field e_x and f the
  // load of a unit acceleration e_x; ∫ρ v_i dV = v · f(e_i).
  const Eigen::VectorXd unit_x = method.interpolate([](const Eigen::Vector3d&) { return Eigen::Vector3d::UnitX(); });
  for (int i = 0; i < 3; ++i) {
    const Eigen::VectorXd load = discretization.body_force(Eigen::Vector3d::Unit(i));
    if (i == 0) measures.mass = unit_x.dot(load);
    measures.momentum[i] = state.velocity.dot(load);
  }
  if (const std::optional<FieldQuadrature> quadrature = method.field_quadrature(0)) {
    double volume = 0;
    for (int e = 0; e < quadrature->elements->size(); ++e)
      for (double weight : (*quadrature->elements)[e].weights) volume += weight;
    measures.volume = volume;
  }
  measures.energy = integrator.kinetic_energy(state) + discretization.energy(state.displacement);
  return measures;
}

nlohmann::json conservation_json(const BodyMeasures& before, const BodyMeasures& after) {
  nlohmann::json result;
  result["mass_change"] = relative_change(before.mass, after.mass);
  result["volume_change"] = before.volume && after.volume ? nlohmann::json(relative_change(*before.volume, *after.volume))
                                                          : nlohmann::json(nullptr);
  const double momentum_scale = std::max(before.momentum.norm(), after.momentum.norm());
  result["momentum_change"] = momentum_scale > 0 ? (after.momentum - before.momentum).norm() / momentum_scale : 0.0;
  result["energy_before_j"] = before.energy;
  result["energy_jump_j"] = after.energy - before.energy;
  result["energy_jump_relative"] =
      before.energy != 0 ? nlohmann::json((after.energy - before.energy) / std::abs(before.energy)) : nlohmann::json(nullptr);
  return result;
}

}  // namespace altfem
