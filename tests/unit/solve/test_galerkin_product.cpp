// galerkin_product: Pᵀ A P against Eigen's two sparse products on random symmetric A and
// random P of several shapes (empty columns and rows of P, 1 × 1, more coarse than fine
// unknowns, rows of P sharing a pattern and columns of A sharing one, as DG's cell blocks
// do), and on the two-level test problem's aggregates. The result must match to 1e-13
// relative, be compressed, exactly symmetric, with sorted rows and no entry outside
// Eigen's pattern. Its two parts on their own: identical_pattern_classes on a small pattern,
// symmetric_from_upper on unsorted ranges.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <vector>

#include "shared/solve/galerkin_product.hpp"
#include "shared/solve/identical_pattern_classes.hpp"
#include "shared/solve/symmetric_from_upper.hpp"
#include "tests/unit/solve/test_matrices.hpp"

namespace altfem {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// A random symmetric n × n matrix (both triangles) whose rows come in blocks of `block`
/// unknowns with one pattern (each block couples to a random set of blocks), so that
/// columns of A share patterns; `density` is the chance that two blocks couple.
SparseMatrix random_symmetric(int size, int block, double density, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0), chance(0.0, 1.0);
  std::vector<Eigen::Triplet<double>> entries;
  const int blocks = (size + block - 1) / block;
  for (int b = 0; b < blocks; ++b)
    for (int c = b; c < blocks; ++c) {
      if (c != b && chance(random) > density) continue;
      for (int i = b * block; i < std::min(size, (b + 1) * block); ++i)
        for (int j = c * block; j < std::min(size, (c + 1) * block); ++j) {
          if (c == b && j < i) continue;
          const double value = uniform(random);
          entries.emplace_back(i, j, value);
          if (i != j) entries.emplace_back(j, i, value);
        }
    }
  SparseMatrix matrix(size, size);
  matrix.setFromTriplets(entries.begin(), entries.end());
  return matrix;
}

/// A random n × m prolongation: each row, unless it is one of `empty_rows`, has up to
/// `per_row` entries in random columns, and the rows come in groups of `group` consecutive
/// rows sharing their pattern; the columns in `empty_columns` are left empty.
SparseMatrix random_prolongation(int fine, int coarse, int per_row, int group, const std::vector<int>& empty_rows,
                                 const std::vector<int>& empty_columns, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::uniform_int_distribution<int> column(0, coarse - 1);
  std::vector<Eigen::Triplet<double>> entries;
  std::vector<int> pattern;
  for (int row = 0; row < fine; ++row) {
    if (row % group == 0) {
      pattern.clear();
      for (int k = 0; k < per_row; ++k) pattern.push_back(column(random));
    }
    if (std::find(empty_rows.begin(), empty_rows.end(), row) != empty_rows.end()) continue;
    for (int col : pattern)
      if (std::find(empty_columns.begin(), empty_columns.end(), col) == empty_columns.end())
        entries.emplace_back(row, col, uniform(random));  // repeated columns are summed
  }
  SparseMatrix prolongation(fine, coarse);
  prolongation.setFromTriplets(entries.begin(), entries.end());
  return prolongation;
}

/// `matrix` (compressed) with the row indices of every column in decreasing order.
SparseMatrix reversed_columns(SparseMatrix matrix) {
  for (Eigen::Index col = 0; col < matrix.outerSize(); ++col) {
    std::reverse(matrix.innerIndexPtr() + matrix.outerIndexPtr()[col],
                 matrix.innerIndexPtr() + matrix.outerIndexPtr()[col + 1]);
    std::reverse(matrix.valuePtr() + matrix.outerIndexPtr()[col], matrix.valuePtr() + matrix.outerIndexPtr()[col + 1]);
  }
  return matrix;
}

void expect_matches_eigen(const SparseMatrix& matrix, const SparseMatrix& prolongation) {
  const SparseMatrix restriction = prolongation.transpose();
  const SparseMatrix expected = restriction * (matrix * prolongation);
  const SparseMatrix product = galerkin_product(matrix, prolongation, restriction);
  ASSERT_EQ(product.rows(), prolongation.cols());
  ASSERT_EQ(product.cols(), prolongation.cols());
  EXPECT_TRUE(product.isCompressed());
  EXPECT_LE((product - expected).norm(), 1e-13 * expected.norm());
  EXPECT_EQ((product - SparseMatrix(product.transpose())).norm(), 0.0);  // exactly symmetric
  for (Eigen::Index j = 0; j < product.outerSize(); ++j)
    for (int at = product.outerIndexPtr()[j]; at < product.outerIndexPtr()[j + 1]; ++at) {
      const int row = product.innerIndexPtr()[at];
      if (at > product.outerIndexPtr()[j]) {
        EXPECT_LT(product.innerIndexPtr()[at - 1], row) << "column " << j;
      }
      bool in_eigen_pattern = false;
      for (SparseMatrix::InnerIterator entry(expected, j); entry; ++entry) in_eigen_pattern |= entry.row() == row;
      EXPECT_TRUE(in_eigen_pattern) << "(" << row << ", " << j << ") is not in Eigen's pattern";
    }
}

TEST(GalerkinProduct, MatchesEigenOnRandomBlockMatrices) {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    // DG-like: blocks of 12 unknowns, P rows in groups of 4 with 8 entries.
    expect_matches_eigen(random_symmetric(240, 12, 0.1, seed), random_prolongation(240, 60, 8, 4, {}, {}, seed));
    // No shared patterns at all.
    expect_matches_eigen(random_symmetric(150, 1, 0.05, seed), random_prolongation(150, 40, 3, 1, {}, {}, seed));
  }
}

TEST(GalerkinProduct, EmptyColumnsAndRowsOfTheProlongation) {
  const SparseMatrix matrix = random_symmetric(120, 6, 0.2, 4);
  // Empty rows spread and in a run (as DG's quadratic monomials under a vertex space).
  expect_matches_eigen(matrix, random_prolongation(120, 30, 5, 3, {0, 7, 50, 51, 52, 53, 54, 119}, {}, 4));
  expect_matches_eigen(matrix, random_prolongation(120, 30, 5, 3, {}, {0, 13, 29}, 5));
  SparseMatrix all_zero_row = random_prolongation(120, 30, 5, 3, {}, {}, 6);
  for (Eigen::Index col = 0; col < all_zero_row.cols(); ++col)
    for (SparseMatrix::InnerIterator entry(all_zero_row, col); entry; ++entry)
      if (entry.row() == 17) entry.valueRef() = 0.0;  // stored zeros: a row with a pattern but no values
  expect_matches_eigen(matrix, all_zero_row);
  expect_matches_eigen(matrix, SparseMatrix(120, 30));  // P = 0
}

TEST(GalerkinProduct, SmallAndWideShapes) {
  SparseMatrix one(1, 1);
  one.insert(0, 0) = 3.0;
  SparseMatrix half(1, 1);
  half.insert(0, 0) = 0.5;
  half.makeCompressed();
  one.makeCompressed();
  expect_matches_eigen(one, half);
  EXPECT_DOUBLE_EQ(galerkin_product(one, half, SparseMatrix(half.transpose())).coeff(0, 0), 0.75);
  expect_matches_eigen(random_symmetric(20, 2, 0.5, 7), random_prolongation(20, 35, 4, 2, {}, {}, 7));  // m > n
  expect_matches_eigen(random_symmetric(30, 3, 0.3, 8), random_prolongation(30, 1, 1, 1, {}, {}, 8));   // m = 1
}

TEST(GalerkinProduct, UncompressedAndUnsortedInputs) {
  const SparseMatrix matrix = random_symmetric(90, 3, 0.2, 9);
  SparseMatrix prolongation = random_prolongation(90, 25, 4, 3, {}, {}, 9);
  SparseMatrix uncompressed_matrix = matrix;
  uncompressed_matrix.insert(0, 89) = 0.0;  // insert() leaves it uncompressed
  uncompressed_matrix.insert(89, 0) = 0.0;
  ASSERT_FALSE(uncompressed_matrix.isCompressed());
  SparseMatrix uncompressed_prolongation = prolongation;
  uncompressed_prolongation.insert(5, 24) = 0.0;
  ASSERT_FALSE(uncompressed_prolongation.isCompressed());
  const SparseMatrix restriction = SparseMatrix(uncompressed_prolongation.transpose());
  const SparseMatrix expected = restriction * (uncompressed_matrix * uncompressed_prolongation);
  const SparseMatrix product = galerkin_product(uncompressed_matrix, uncompressed_prolongation, restriction);
  EXPECT_TRUE(product.isCompressed());
  EXPECT_LE((product - expected).norm(), 1e-13 * expected.norm());
  // Pᵀ and A with the rows of each column reversed: Pᵀ is sorted internally before use, A's
  // order only decides which columns are grouped.
  const SparseMatrix reversed_restriction = reversed_columns(restriction);
  const SparseMatrix reversed_matrix = reversed_columns(matrix);
  EXPECT_LE((galerkin_product(uncompressed_matrix, uncompressed_prolongation, reversed_restriction) - expected).norm(),
            1e-13 * expected.norm());
  // (the explicit zeros added above leave the product's values unchanged)
  EXPECT_LE((galerkin_product(reversed_matrix, prolongation, SparseMatrix(prolongation.transpose())) - expected).norm(),
            1e-13 * expected.norm());
}

TEST(GalerkinProduct, AggregatesOfTheElasticityLikeLaplacian) {
  const int grid = 6, aggregates = 3;
  std::vector<Eigen::Triplet<double>> entries;
  for (int node = 0; node < grid * grid * grid; ++node) {
    const int i = node % grid, j = node / grid % grid, k = node / (grid * grid);
    const int aggregate = i / 2 + aggregates * (j / 2 + aggregates * (k / 2));
    for (int c = 0; c < 3; ++c) entries.emplace_back(3 * node + c, 3 * aggregate + c, 1.0);
  }
  SparseMatrix prolongation(3 * grid * grid * grid, 3 * aggregates * aggregates * aggregates);
  prolongation.setFromTriplets(entries.begin(), entries.end());
  expect_matches_eigen(testing::elasticity_like_laplacian(grid), prolongation);
}

TEST(GalerkinProduct, SameResultOnAnyNumberOfThreads) {
  // Each column is formed by one thread in a fixed order: the threads change nothing, bit for bit.
  const SparseMatrix matrix = random_symmetric(300, 12, 0.08, 11),
                     prolongation = random_prolongation(300, 77, 8, 4, {}, {}, 11);
  const SparseMatrix restriction = prolongation.transpose();
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const SparseMatrix serial = galerkin_product(matrix, prolongation, restriction);
  omp_set_num_threads(3);
  const SparseMatrix parallel = galerkin_product(matrix, prolongation, restriction);
  omp_set_num_threads(threads);
  ASSERT_EQ(serial.nonZeros(), parallel.nonZeros());
  EXPECT_EQ((serial - parallel).norm(), 0.0);
}

TEST(GalerkinProduct, RejectsShapesThatDoNotFit) {
  const SparseMatrix matrix = random_symmetric(10, 1, 0.3, 10),
                     prolongation = random_prolongation(10, 4, 2, 1, {}, {}, 10);
  EXPECT_THROW(galerkin_product(matrix, prolongation, prolongation), std::invalid_argument);
  EXPECT_THROW(galerkin_product(SparseMatrix(9, 9), prolongation, SparseMatrix(prolongation.transpose())),
               std::invalid_argument);
}

TEST(IdenticalPatternClasses, SameRowsInTheSameOrderShareAClass) {
  // Columns: {0, 2}, {1}, {0, 2}, {2, 0} (same set, other order), {} (not kept), {1}, {}.
  const int outer[] = {0, 2, 3, 5, 7, 7, 8, 8};
  const int inner[] = {0, 2, 1, 0, 2, 2, 0, 1};
  const std::vector<char> kept = {1, 1, 1, 1, 0, 1, 1};
  int class_count = 0;
  EXPECT_EQ(identical_pattern_classes(outer, inner, kept, class_count), (std::vector<int>{0, 1, 0, 2, -1, 1, 3}));
  EXPECT_EQ(class_count, 4);
}

TEST(SymmetricFromUpper, MirrorsUnsortedRangesIntoSortedColumns) {
  // The upper triangle of [[1, 2, 0], [2, 3, 4], [0, 4, 5]] in two ranges, rows unsorted.
  std::vector<UpperColumns> ranges(2);
  ranges[0] = {0, 2, {0, 1, 3}, {0, 1, 0}, {1.0, 3.0, 2.0}};
  ranges[1] = {2, 3, {0, 2}, {2, 1, 99}, {5.0, 4.0, 99.0}};  // longer arrays than outer says
  const SparseMatrix symmetric = symmetric_from_upper(ranges, 3);
  Eigen::Matrix3d expected;
  expected << 1, 2, 0, 2, 3, 4, 0, 4, 5;
  EXPECT_EQ(Eigen::Matrix3d(symmetric), expected);
  EXPECT_EQ(symmetric.nonZeros(), 7);
  EXPECT_TRUE(symmetric.isCompressed());
  for (Eigen::Index j = 0; j < 3; ++j)
    for (int at = symmetric.outerIndexPtr()[j] + 1; at < symmetric.outerIndexPtr()[j + 1]; ++at)
      EXPECT_LT(symmetric.innerIndexPtr()[at - 1], symmetric.innerIndexPtr()[at]);
}

}  // namespace
}  // namespace altfem
