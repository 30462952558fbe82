#pragma once
// The volume matrices of one DG element for isotropic linear elasticity, integrated
// exactly (Kaufmann et al. 2009 §5, Appendix A): products of monomials and of their
// derivatives are monomials, whose integrals over any polyhedron — convex or not — the
// divergence theorem gives exactly (shared/geometry/polyhedron_moments). No quadrature.
#include <Eigen/Core>

#include "dg/monomial_basis.hpp"
#include "shared/geometry/polyhedron.hpp"

namespace altfem::dg {

struct ElementMatrices {
  /// 3n × 3n, local DOF 3a+i: ∫ 2μ ε(φ_b e_k) : ε(φ_a e_i) + λ div(φ_b e_k) div(φ_a e_i) dV.
  Eigen::MatrixXd stiffness;
  /// n × n: ρ ∫ φ_a φ_b dV (the same for each component).
  Eigen::MatrixXd mass;
  /// n: ∫ φ_a dV (the load of a unit body force per unit density).
  Eigen::VectorXd integrals;
};

/// λ, μ: Lamé parameters; density ρ.
ElementMatrices exact_element_matrices(const Polyhedron& element, const MonomialBasis& basis, double lambda, double mu,
                                       double density);

}  // namespace altfem::dg
