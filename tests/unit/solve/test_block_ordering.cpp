#include "shared/solve/block_fill_reducing_ordering.hpp"
#include "shared/solve/linear_solver.hpp"
#include "tests/unit/solve/test_matrices.hpp"

#include <gtest/gtest.h>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <numeric>

namespace altfem {
namespace {

// The scalar 7-point Laplacian: elasticity_like_laplacian's node graph.
Eigen::SparseMatrix<double> scalar_laplacian(int n) {
  const Eigen::SparseMatrix<double> blocked = testing::elasticity_like_laplacian(n);
  Eigen::SparseMatrix<double> scalar(blocked.rows() / 3, blocked.cols() / 3);
  std::vector<Eigen::Triplet<double>> entries;
  for (int column = 0; column < blocked.cols(); column += 3)
    for (Eigen::SparseMatrix<double>::InnerIterator entry(blocked, column); entry; ++entry)
      if (entry.row() % 3 == 0) entries.emplace_back(entry.row() / 3, column / 3, entry.value());
  scalar.setFromTriplets(entries.begin(), entries.end());
  return scalar;
}

// Runs of `size` consecutive unknowns: starts 0, size, 2 size, …, count.
std::vector<int> runs_of(int size, int count) {
  std::vector<int> starts;
  for (int start = 0; start <= count; start += size) starts.push_back(start);
  return starts;
}

TEST(BlockOrdering, SupervariablesAreTheNodesOrElementsOfThePattern) {
  const Eigen::SparseMatrix<double> elasticity = testing::elasticity_like_laplacian(4);
  EXPECT_EQ(supervariable_starts(elasticity), runs_of(3, static_cast<int>(elasticity.cols())));
  const Eigen::SparseMatrix<double> scalar = scalar_laplacian(4);
  EXPECT_EQ(supervariable_starts(scalar), runs_of(1, static_cast<int>(scalar.cols())));
  // A DG-like matrix: 12 coefficients per element, dense element blocks coupling each
  // element of a chain of 5 with its neighbours.
  const int elements = 5, size = 12;
  std::vector<Eigen::Triplet<double>> entries;
  for (int element = 0; element < elements; ++element)
    for (int neighbour = std::max(element - 1, 0); neighbour <= std::min(element + 1, elements - 1); ++neighbour)
      for (int i = 0; i < size; ++i)
        for (int j = 0; j < size; ++j) entries.emplace_back(size * element + i, size * neighbour + j, 1.0);
  Eigen::SparseMatrix<double> chain(size * elements, size * elements);
  chain.setFromTriplets(entries.begin(), entries.end());
  EXPECT_EQ(supervariable_starts(chain), runs_of(size, size * elements));
}

TEST(BlockOrdering, AMissingEntryInsideABlockSplitsItsSupervariable) {
  Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(3);
  // Drop the coupling between unknowns 0 and 1 of node 0 (both triangles).
  matrix.coeffRef(0, 1) = 0;
  matrix.coeffRef(1, 0) = 0;
  matrix.prune(0.0);
  const std::vector<int> starts = supervariable_starts(matrix);
  ASSERT_GE(starts.size(), 4u);
  EXPECT_EQ(std::vector<int>(starts.begin(), starts.begin() + 4), (std::vector<int>{0, 1, 2, 3}));
}

TEST(BlockOrdering, KeepsTheUnknownsOfANodeTogether) {
  const Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(6);
  const std::vector<int> order = block_fill_reducing_ordering(matrix);
  ASSERT_EQ(order.size(), static_cast<std::size_t>(matrix.rows()));
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  std::vector<int> identity(order.size());
  std::iota(identity.begin(), identity.end(), 0);
  EXPECT_EQ(sorted, identity);  // a permutation
  for (std::size_t k = 0; k < order.size(); k += 3) {
    EXPECT_EQ(order[k] % 3, 0);
    EXPECT_EQ(order[k + 1], order[k] + 1);
    EXPECT_EQ(order[k + 2], order[k] + 2);
  }
}

TEST(BlockOrdering, CholmodFactorHasFarLessFillThanTheNaturalOrder) {
  const Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(10);
  auto solver = make_linear_solver({});
  solver->analyze(matrix);
  const double entries = solver->statistics().factor_entries;
  const double lower_entries = static_cast<double>(matrix.nonZeros() + matrix.rows()) / 2;
  EXPECT_GE(entries, lower_entries);
  EXPECT_GT(solver->statistics().factorisation_flops, entries);
  // The natural (lexicographic) order fills the whole band of width 3n²; nested
  // dissection of a 10³ grid stores well under half of that.
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>> natural(matrix);
  ASSERT_EQ(natural.info(), Eigen::Success);
  const Eigen::SparseMatrix<double> natural_factor = natural.matrixL();
  EXPECT_LT(entries, 0.5 * static_cast<double>(natural_factor.nonZeros()));
}

}  // namespace
}  // namespace altfem
