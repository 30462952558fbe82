#include "shared/solve/krylov.hpp"

#include "shared/common/error.hpp"

#include <cmath>
#include <sstream>

namespace altfem {

void symmetric_multiply(const Eigen::SparseMatrix<double>& matrix, const Eigen::VectorXd& vector,
                        Eigen::VectorXd& product) {
  // Aᵀ = A, and Eigen runs a transposed (row-major) sparse × dense product in
  // parallel with OpenMP, while the column-major one is sequential.
  product.noalias() = matrix.transpose() * vector;
}

double true_residual(const Eigen::SparseMatrix<double>& matrix, const Eigen::VectorXd& rhs,
                     const Eigen::VectorXd& solution, Eigen::VectorXd& residual) {
  symmetric_multiply(matrix, solution, residual);
  residual = rhs - residual;
  return residual.norm() / rhs.norm();
}

bool has_converged(std::string_view method, int iterations, double relative_residual, const KrylovSettings& settings) {
  if (relative_residual <= settings.tolerance) return true;
  if (!std::isfinite(relative_residual)) throw_breakdown(method, iterations, "the residual is not finite");
  if (iterations < settings.max_iterations) return false;
  std::ostringstream message;
  message << method << " did not converge in " << iterations << " iterations (relative residual " << relative_residual
          << " > tolerance " << settings.tolerance << ")";
  throw NumericalError(message.str());
}

void throw_breakdown(std::string_view method, int iterations, std::string_view why) {
  std::ostringstream message;
  message << method << " broke down at iteration " << iterations << ": " << why;
  throw KrylovBreakdown(message.str());
}

}  // namespace altfem
