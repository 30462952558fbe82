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
/// The six rigid-body modes in the method's basis (#dofs × 6): the translations along x,
/// y, z, then the infinitesimal rotations e_k × x about them. They span the kernel of
/// the stiffness without Dirichlet conditions, which algebraic multigrid for elasticity
/// builds its coarse spaces from (petsc_solver.hpp).
Eigen::MatrixXd rigid_body_modes(const MethodInstance& method);
/// The coefficients (#dofs) of the initial velocity v + ω × (x − c) (c: the scene's
/// centre, or else the centre of mass).
Eigen::VectorXd initial_velocity(const MethodInstance& method, const InitialConditions& initial);

}  // namespace altfem
