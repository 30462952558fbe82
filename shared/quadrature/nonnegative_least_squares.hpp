#pragma once
// Lawson & Hanson's active-set algorithm for min ‖A x − b‖₂ subject to x >= 0
// (Solving Least Squares Problems, 1974, ch. 23). Its passive set only ever holds
// linearly independent columns, so on a consistent system it returns a solution with
// at most rank(A) non-zeros: the LP-free route to a basic feasible point in quadrature
// simplification (Longva et al. 2020, §4.4.2).
#include <Eigen/Core>

namespace altfem {

struct NonnegativeLeastSquaresResult {
  Eigen::VectorXd solution;  ///< #columns of A, every entry >= 0
  double residual_norm;      ///< ‖A x − b‖₂
  int iterations;            ///< outer iterations (columns added)
  bool converged;            ///< the optimality conditions held before the iteration limit
};

/// A: #rows × #columns, b: #rows. Stops when no column's gradient (A^T (b − A x))_j
/// exceeds gradient_tolerance · ‖b‖₂, or after 3 · #columns outer iterations.
NonnegativeLeastSquaresResult nonnegative_least_squares(const Eigen::Ref<const Eigen::MatrixXd>& A,
                                                        const Eigen::Ref<const Eigen::VectorXd>& b,
                                                        double gradient_tolerance = 1e-14);

}  // namespace altfem
