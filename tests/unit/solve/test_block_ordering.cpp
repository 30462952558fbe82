#include "shared/solve/block_fill_reducing_ordering.hpp"
#include "shared/solve/linear_solver.hpp"
#include "tests/unit/solve/test_matrices.hpp"

#include <Eigen/SparseCholesky>
#include <gtest/gtest.h>

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

TEST(BlockOrdering, DetectsTheBlockSizeOfThePattern) {
  EXPECT_EQ(sparsity_block_size(testing::elasticity_like_laplacian(4)), 3);
  EXPECT_EQ(sparsity_block_size(scalar_laplacian(4)), 1);
  // Two coupled unknowns per node: 2 × 2 blocks.
  const Eigen::SparseMatrix<double> scalar = scalar_laplacian(4);
  Eigen::SparseMatrix<double> pairs(2 * scalar.rows(), 2 * scalar.cols());
  std::vector<Eigen::Triplet<double>> entries;
  for (int column = 0; column < scalar.cols(); ++column)
    for (Eigen::SparseMatrix<double>::InnerIterator entry(scalar, column); entry; ++entry)
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b)
          entries.emplace_back(2 * entry.row() + a, 2 * column + b, entry.value() * (a == b ? 2.0 : 1.0));
  pairs.setFromTriplets(entries.begin(), entries.end());
  EXPECT_EQ(sparsity_block_size(pairs), 2);
}

TEST(BlockOrdering, AMissingEntryInsideABlockBreaksTheBlocks) {
  Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(3);
  // Drop the coupling between unknowns 0 and 1 of node 0 (both triangles).
  matrix.coeffRef(0, 1) = 0;
  matrix.coeffRef(1, 0) = 0;
  matrix.prune(0.0);
  EXPECT_EQ(sparsity_block_size(matrix), 1);
}

TEST(BlockOrdering, KeepsTheUnknownsOfANodeTogether) {
  const Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(6);
  const std::vector<int> order = block_fill_reducing_ordering(matrix, 3);
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
