#include "shared/quadrature/basic_feasible_point.hpp"

#include <ClpSimplex.hpp>
#include <limits>
#include <vector>

namespace altfem {

std::optional<Eigen::VectorXd> basic_feasible_point(const Eigen::Ref<const Eigen::MatrixXd>& A,
                                                    const Eigen::Ref<const Eigen::VectorXd>& b) {
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
  const std::vector<double> lower(columns, 0.0), upper(columns, COIN_DBL_MAX), objective(columns, 0.0);
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

}  // namespace altfem
