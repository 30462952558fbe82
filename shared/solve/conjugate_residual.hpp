#pragma once
#include "shared/solve/krylov.hpp"

namespace altfem {

/// Vectors (#dofs each) kept between solves so that iterations never allocate.
struct ConjugateResidualWorkspace {
  Eigen::VectorXd residual, preconditioned_residual, matrix_preconditioned_residual, direction, matrix_direction,
      preconditioned_matrix_direction;
};

/// Preconditioned conjugate residual (Saad, 2nd ed., Algorithm 6.20, run in the
/// M-inner product, where M⁻¹A is self-adjoint): minimises ‖r‖ in the M⁻¹ norm
/// over the Krylov space with one product and one preconditioner application per
/// iteration. For a symmetric `matrix` (#dofs × #dofs, both triangles) with an
/// SPD preconditioner (already computed); may break down on indefinite matrices
/// (zᵀAz = 0), where MINRES does not. `solution` (#dofs) holds the initial guess
/// on entry. Stopping rule: krylov.hpp. Throws NumericalError on
/// non-convergence or breakdown.
KrylovResult conjugate_residual(const Eigen::SparseMatrix<double>& matrix, const Preconditioner& preconditioner,
                                const Eigen::VectorXd& rhs, Eigen::VectorXd& solution, const KrylovSettings& settings,
                                ConjugateResidualWorkspace& workspace);

}  // namespace altfem
