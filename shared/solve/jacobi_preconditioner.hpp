#pragma once
#include "shared/solve/preconditioner.hpp"

namespace altfem {

/// Diagonal (Jacobi) preconditioner M = |diag(A)|. The absolute value keeps M
/// positive definite on indefinite systems whose diagonal has both signs, which
/// MINRES requires of its preconditioner; on SPD matrices it is plain Jacobi.
class JacobiPreconditioner final : public Preconditioner {
public:
  /// Throws NumericalError naming the first row whose diagonal entry is zero.
  void compute(const Eigen::SparseMatrix<double>& matrix) override;
  void apply(const Eigen::VectorXd& residual, Eigen::VectorXd& result) const override;

private:
  Eigen::VectorXd inverse_diagonal_;  // #dofs
};

}  // namespace altfem
