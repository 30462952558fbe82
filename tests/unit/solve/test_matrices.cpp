#include "tests/unit/solve/test_matrices.hpp"

#include <vector>

namespace altfem::testing {

Eigen::SparseMatrix<double> elasticity_like_laplacian(int n) {
  const Eigen::Matrix3d block = Eigen::Matrix3d::Identity() + 0.5 * Eigen::Matrix3d::Ones();
  const auto node = [n](int i, int j, int k) { return (k * n + j) * n + i; };
  std::vector<Eigen::Triplet<double>> entries;
  const auto add = [&](int row_node, int column_node, double value) {
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) entries.emplace_back(3 * row_node + a, 3 * column_node + b, value * block(a, b));
  };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        add(node(i, j, k), node(i, j, k), 6.0);
        if (i > 0) add(node(i, j, k), node(i - 1, j, k), -1.0);
        if (i + 1 < n) add(node(i, j, k), node(i + 1, j, k), -1.0);
        if (j > 0) add(node(i, j, k), node(i, j - 1, k), -1.0);
        if (j + 1 < n) add(node(i, j, k), node(i, j + 1, k), -1.0);
        if (k > 0) add(node(i, j, k), node(i, j, k - 1), -1.0);
        if (k + 1 < n) add(node(i, j, k), node(i, j, k + 1), -1.0);
      }
  Eigen::SparseMatrix<double> matrix(3 * n * n * n, 3 * n * n * n);
  matrix.setFromTriplets(entries.begin(), entries.end());
  return matrix;
}

Eigen::SparseMatrix<double> shifted(const Eigen::SparseMatrix<double>& matrix, double shift) {
  Eigen::SparseMatrix<double> identity(matrix.rows(), matrix.cols());
  identity.setIdentity();
  return matrix - shift * identity;
}

Eigen::SparseMatrix<double> saddle_point(int n, int constraints, double c) {
  const Eigen::SparseMatrix<double> stiffness = elasticity_like_laplacian(n);
  const int unknowns = static_cast<int>(stiffness.rows());
  std::vector<Eigen::Triplet<double>> entries;
  for (int column = 0; column < stiffness.outerSize(); ++column)
    for (Eigen::SparseMatrix<double>::InnerIterator entry(stiffness, column); entry; ++entry)
      entries.emplace_back(entry.row(), entry.col(), entry.value());
  for (int constraint = 0; constraint < constraints; ++constraint) {
    for (int unknown = constraint; unknown < unknowns; unknown += constraints) {
      entries.emplace_back(unknowns + constraint, unknown, 1.0);
      entries.emplace_back(unknown, unknowns + constraint, 1.0);
    }
    entries.emplace_back(unknowns + constraint, unknowns + constraint, -c);
  }
  Eigen::SparseMatrix<double> matrix(unknowns + constraints, unknowns + constraints);
  matrix.setFromTriplets(entries.begin(), entries.end());
  return matrix;
}

}  // namespace altfem::testing
