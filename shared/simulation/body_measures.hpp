#pragma once
// What a topology or discretization event must conserve, measured in any basis
// (rigid_motion.hpp's reasoning: every basis reproduces constants, and body_force
// integrates ρ against it): the body's mass ∫ρ dV, its volume ∫dV, its linear momentum
// ∫ρ v dV, and its kinetic plus elastic energy.
#include <Eigen/Core>
#include <array>
#include <nlohmann/json.hpp>
#include <optional>

#include "shared/simulation/method_instance.hpp"
#include "shared/solve/time_integrator.hpp"

namespace altfem {

struct BodyMeasures {
  double mass = 0;                                     ///< ∫ρ dV [kg]
  std::optional<double> volume;                        ///< ∫dV [m³]; nullopt when the method has no volume rule
  Eigen::Vector3d momentum = Eigen::Vector3d::Zero();  ///< ∫ρ v dV [kg m/s]
  double energy = 0;                                   ///< kinetic + elastic [J]
};

/// What the measures need that does not change while the discretization stays (so an
/// event measures it once): the loads of unit accelerations along x, y, z, the mass and
/// the volume (MethodInstance::volume).
struct BodyMeasureBasis {
  std::array<Eigen::VectorXd, 3> unit_loads;  ///< body_force(e_i), #dofs each
  double mass = 0;
  std::optional<double> volume;
};

BodyMeasureBasis body_measure_basis(const MethodInstance& method, const Discretization& discretization);

/// The measures of `state`; `integrator` gives the kinetic energy with the mass its
/// scheme uses, `discretization` the elastic energy.
BodyMeasures measure_body(const BodyMeasureBasis& basis, const Discretization& discretization,
                          const TimeIntegrator& integrator, const State& state);

/// summary.json's record of what an event conserved: relative changes of mass, volume
/// (absent when a method has no volume rule) and momentum (relative to the larger of the
/// two), and the energy's jump (J, and relative to the energy before when that is not 0).
nlohmann::json conservation_json(const BodyMeasures& before, const BodyMeasures& after);

}  // namespace altfem
