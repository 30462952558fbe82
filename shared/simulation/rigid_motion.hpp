#pragma once
// Quantities of rigid motion computed for any method from its basis: every basis
// reproduces affine fields, and body_force integrates ρ against the basis, so
// ∫ρ x dV = Σ_a X_a·f_a with X the coefficients of the field x and f the load of a
// unit acceleration.
#include <Eigen/Core>

#include "shared/scene/scene.hpp"
#include "shared/simulation/method_instance.hpp"

namespace altfem {

/// ∫ρ x dV / ∫ρ dV over the method's discretized body.
Eigen::Vector3d centre_of_mass(const MethodInstance& method);
/// The coefficients (#dofs) of the initial velocity v + ω × (x − c) (c: the scene's
/// centre, or else the centre of mass).
Eigen::VectorXd initial_velocity(const MethodInstance& method, const InitialConditions& initial);

}  // namespace altfem
