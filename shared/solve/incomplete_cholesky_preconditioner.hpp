#pragma once
#include "shared/solve/preconditioner.hpp"

namespace altfem {

/// Incomplete Cholesky preconditioner: Eigen's IncompleteCholesky (Lin & Moré
/// 1999 limited-memory variant, AMD ordering, diagonal scaling). When a pivot
/// fails Eigen retries with a growing diagonal shift, so M stays SPD.
class IncompleteCholeskyPreconditioner final : public Preconditioner {
public:
  /// Throws NumericalError when Eigen reports a failure (e.g. a non-positive diagonal).
  void compute(const Eigen::SparseMatrix<double>& matrix) override;
  void apply(const Eigen::VectorXd& residual, Eigen::VectorXd& result) const override;

private:
  Eigen::IncompleteCholesky<double, Eigen::Lower, Eigen::AMDOrdering<int>> cholesky_;
};

}  // namespace altfem
