#include "shared/quadrature/basic_feasible_point.hpp"

#include <ClpSimplex.hpp>
#include <Eigen/Cholesky>
#include <limits>
#include <vector>

namespace altfem {

namespace {

// min cᵀx subject to A x = b, x >= 0 (Clp, dense columns), or nullopt when not proven optimal.
std::optional<Eigen::VectorXd> solve_standard_lp(const Eigen::Ref<const Eigen::MatrixXd>& A,
                                                 const Eigen::Ref<const Eigen::VectorXd>& b,
                                                 const std::vector<double>& objective) {
  const int rows = static_cast<int>(A.rows()), columns = static_cast<int>(A.cols());
  // Dense column-major storage in Clp's compressed-column form.
  std::vector<CoinBigIndex> starts(columns + 1);
  std::vector<int> row_indices(static_cast<std::size_t>(rows) * columns);
  std::vector<double> values(static_cast<std::size_t>(rows) * columns);
  for (int j = 0; j < columns; ++j) {
    starts[j] = static_cast<CoinBigIndex>(j) * rows;
    for (int i = 0; i < rows; ++i) {
      row_indices[static_cast<std::size_t>(j) * rows + i] = i;
      values[static_cast<std::size_t>(j) * rows + i] = A(i, j);
    }
  }
  starts[columns] = static_cast<CoinBigIndex>(columns) * rows;
  const std::vector<double> lower(columns, 0.0), upper(columns, COIN_DBL_MAX);
  const std::vector<double> rhs(b.data(), b.data() + rows);

  ClpSimplex simplex;
  simplex.setLogLevel(0);
  simplex.loadProblem(columns, rows, starts.data(), row_indices.data(), values.data(), lower.data(), upper.data(),
                      objective.data(), rhs.data(), rhs.data());
  // Tighter than Clp's default 1e-7: the weights must reproduce the moments to rounding.
  simplex.setPrimalTolerance(1e-12);
  simplex.primal();
  if (!simplex.isProvenOptimal()) return std::nullopt;
  const double* solution = simplex.primalColumnSolution();
  Eigen::VectorXd x(columns);
  for (int j = 0; j < columns; ++j) x(j) = solution[j] > 0.0 ? solution[j] : 0.0;
  return x;
}

}  // namespace

std::optional<Eigen::VectorXd> basic_feasible_point(const Eigen::Ref<const Eigen::MatrixXd>& A,
                                                    const Eigen::Ref<const Eigen::VectorXd>& b) {
  // No objective: Clp's phase 1 stops at the first feasible basis.
  return solve_standard_lp(A, b, std::vector<double>(A.cols(), 0.0));
}

std::optional<Eigen::VectorXd> spread_feasible_point(const Eigen::Ref<const Eigen::MatrixXd>& A,
                                                     const Eigen::Ref<const Eigen::VectorXd>& b,
                                                     const Eigen::Ref<const Eigen::VectorXd>& prior) {
  // Columns [A | A·prior] over (s, t): maximise t, i.e. minimise −t.
  Eigen::MatrixXd extended(A.rows(), A.cols() + 1);
  extended.leftCols(A.cols()) = A;
  extended.col(A.cols()) = A * prior;
  std::vector<double> objective(A.cols() + 1, 0.0);
  objective.back() = -1.0;
  const std::optional<Eigen::VectorXd> solution = solve_standard_lp(extended, b, objective);
  if (!solution || (*solution)[A.cols()] <= 0.0) return std::nullopt;
  Eigen::VectorXd x = solution->head(A.cols()) + (*solution)[A.cols()] * prior;
  // Clp meets A x = b to its tolerance; the minimum-norm correction Aᵀ(AAᵀ)⁻¹(b − Ax)
  // meets it to round-off, and is far smaller than t·prior, which keeps x positive.
  const Eigen::MatrixXd normal = A * A.transpose();
  x += A.transpose() * normal.ldlt().solve(b - A * x);
  if (x.minCoeff() <= 0.0) return std::nullopt;
  return x;
}

}  // namespace altfem
