#include "shared/solve/jacobi_preconditioner.hpp"

#include "shared/common/error.hpp"

#include <cmath>
#include <string>

namespace altfem {

void JacobiPreconditioner::compute(const Eigen::SparseMatrix<double>& matrix) {
  const Eigen::VectorXd diagonal = matrix.diagonal();
  for (Eigen::Index row = 0; row < diagonal.size(); ++row)
    if (diagonal[row] == 0.0)
      throw NumericalError("Jacobi preconditioner: diagonal entry of row " + std::to_string(row) + " is zero");
  inverse_diagonal_ = diagonal.cwiseAbs().cwiseInverse();
}

void JacobiPreconditioner::apply(const Eigen::VectorXd& residual, Eigen::VectorXd& result) const {
  result = inverse_diagonal_.cwiseProduct(residual);
}

}  // namespace altfem
