#include "shared/solve/incomplete_cholesky_preconditioner.hpp"

#include "shared/common/error.hpp"

#include <string>

namespace altfem {

void IncompleteCholeskyPreconditioner::compute(const Eigen::SparseMatrix<double>& matrix) {
  cholesky_.compute(matrix);
  if (cholesky_.info() != Eigen::Success)
    throw NumericalError("incomplete Cholesky preconditioner: factorisation failed (Eigen status " +
                         std::to_string(static_cast<int>(cholesky_.info())) + ")");
}

void IncompleteCholeskyPreconditioner::apply(const Eigen::VectorXd& residual, Eigen::VectorXd& result) const {
  // Eigen evaluates the scaling, permutations and triangular solves in place in `result`.
  result = cholesky_.solve(residual);
}

}  // namespace altfem
