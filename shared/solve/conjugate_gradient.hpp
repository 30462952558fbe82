#pragma once
#include "shared/solve/krylov.hpp"

namespace altfem {

/// Vectors (#dofs each) kept between solves so that iterations never allocate.
struct ConjugateGradientWorkspace {
  Eigen::VectorXd residual, preconditioned_residual, direction, matrix_direction;
};

/// Preconditioned conjugate gradient (Saad, Iterative Methods for Sparse Linear
/// Systems, 2nd ed., Algorithm 9.1) for a symmetric positive definite `matrix`
/// (#dofs × #dofs, both triangles) and an SPD preconditioner (already computed).
/// `solution` (#dofs) holds the initial guess on entry. Stopping rule: krylov.hpp.
/// Throws NumericalError on non-convergence, or when pᵀAp ≤ 0 (matrix not
/// positive definite) or rᵀM⁻¹r < 0 (preconditioner not positive definite).
KrylovResult conjugate_gradient(const Eigen::SparseMatrix<double>& matrix, const Preconditioner& preconditioner,
                                const Eigen::VectorXd& rhs, Eigen::VectorXd& solution, const KrylovSettings& settings,
                                ConjugateGradientWorkspace& workspace);

}  // namespace altfem
