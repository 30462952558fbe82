#pragma once
// What the Krylov methods (conjugate_gradient, minres, conjugate_residual)
// share: their stopping rule, result, and the symmetric sparse product.
//
// Stopping rule, the same for every method: ‖b − A x‖₂ ≤ tolerance · ‖b‖₂ with
// the TRUE residual. Each method iterates on its cheap recurrence estimate; when
// the estimate passes, the true residual is computed, and if rounding has made
// the two drift apart the method restarts from the current iterate.
#include "shared/solve/preconditioner.hpp"

#include <Eigen/Sparse>

#include <string_view>

#include "shared/common/error.hpp"

namespace altfem {

struct KrylovSettings {
  double tolerance = 1e-10;  ///< on the relative true residual ‖b − A x‖₂ / ‖b‖₂
  int max_iterations = 10000;
};

struct KrylovResult {
  int iterations = 0;
  double relative_residual = 0;  ///< true ‖b − A x‖₂ / ‖b‖₂ at return
};

/// product = matrix · vector for a symmetric matrix (#dofs × #dofs, both
/// triangles); vector and product are #dofs and must not alias.
void symmetric_multiply(const Eigen::SparseMatrix<double>& matrix, const Eigen::VectorXd& vector,
                        Eigen::VectorXd& product);

/// residual = rhs − matrix · solution; returns ‖residual‖₂ / ‖rhs‖₂ (‖rhs‖₂ > 0).
double true_residual(const Eigen::SparseMatrix<double>& matrix, const Eigen::VectorXd& rhs,
                     const Eigen::VectorXd& solution, Eigen::VectorXd& residual);

/// Whether the true relative residual meets the tolerance. Otherwise throws
/// NumericalError "<method> did not converge in N iterations (relative residual
/// r > tolerance t)" when no iterations are left, or "<method> broke down ..."
/// when the residual is not finite; returns false when iterating may go on.
bool has_converged(std::string_view method, int iterations, double relative_residual, const KrylovSettings& settings);

/// A Krylov method that cannot go on: a curvature pᵀAp ≤ 0 where the matrix should be
/// positive definite, a preconditioner that is not, a residual that is not finite.
class KrylovBreakdown : public NumericalError {
public:
  using NumericalError::NumericalError;
};

/// Throws KrylovBreakdown "<method> broke down at iteration N: <why>".
[[noreturn]] void throw_breakdown(std::string_view method, int iterations, std::string_view why);

}  // namespace altfem
