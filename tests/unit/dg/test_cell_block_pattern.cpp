// dg/cell_block_pattern: blocks added in place land where a dense sum puts them, and the
// pattern holds exactly the coupled cells' whole blocks (zeros stored), or a cell's
// diagonal alone where asked.
#include <gtest/gtest.h>

#include "dg/cell_block_pattern.hpp"

namespace altfem::dg {
namespace {

TEST(CellBlockPattern, AddedBlocksEqualTheirDenseSum) {
  // Cells of 1, 4 and 10 functions (3, 12 and 30 DOFs); 0–2 and 1–2 share faces (1–2
  // twice), 0 and 1 do not.
  const std::vector<int> offsets{0, 1, 5, 15};
  const CellBlockPattern pattern(offsets, {{0, 2}, {2, 1}, {1, 2}});
  Eigen::SparseMatrix<double> matrix;
  pattern.make_zero_matrix(matrix);
  ASSERT_EQ(matrix.rows(), 45);
  // Columns of cell 0: rows of cells 0, 2; of cell 1: 1, 2; of cell 2: all.
  EXPECT_EQ(matrix.nonZeros(), 3 * (3 + 30) + 12 * (12 + 30) + 30 * 45);
  EXPECT_TRUE(matrix.isCompressed());

  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(45, 45);
  const auto dofs = [&](int cell) { return std::pair{3 * offsets[cell], 3 * (offsets[cell + 1] - offsets[cell])}; };
  std::srand(7);
  for (const auto& [row, column] : {std::pair{0, 0}, {2, 0}, {0, 2}, {1, 2}, {2, 1}, {2, 2}, {2, 1}, {1, 1}}) {
    const auto [row_first, rows] = dofs(row);
    const auto [column_first, columns] = dofs(column);
    const Eigen::MatrixXd block = Eigen::MatrixXd::Random(rows, columns);
    pattern.add_block(matrix, row, column, block);
    dense.block(row_first, column_first, rows, columns) += block;
  }
  EXPECT_EQ((Eigen::MatrixXd(matrix) - dense).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_THROW(pattern.add_block(matrix, 0, 1, Eigen::MatrixXd::Zero(3, 12)), std::logic_error);
  EXPECT_THROW(pattern.add_block(matrix, 0, 2, Eigen::MatrixXd::Zero(3, 12)), std::logic_error);
}

// A rank's share of K (docs/scaling.md): a cell of another rank that none of its faces
// touches keeps its diagonal entries alone, and takes no block and no coupling.
TEST(CellBlockPattern, ADiagonalOnlyCellHoldsItsDiagonalAlone) {
  const std::vector<int> offsets{0, 1, 5, 15};
  const CellBlockPattern pattern(offsets, {{0, 1}}, {0, 0, 1});
  Eigen::SparseMatrix<double> matrix;
  pattern.make_zero_matrix(matrix);
  ASSERT_EQ(matrix.rows(), 45);
  // Columns of cells 0 and 1: rows of cells 0 and 1; of cell 2: its own row alone.
  EXPECT_EQ(matrix.nonZeros(), (3 + 12) * (3 + 12) + 30);
  for (int column = 15; column < 45; ++column) {
    EXPECT_EQ(matrix.outerIndexPtr()[column + 1] - matrix.outerIndexPtr()[column], 1);
    EXPECT_EQ(matrix.innerIndexPtr()[matrix.outerIndexPtr()[column]], column);
  }
  pattern.add_block(matrix, 1, 0, Eigen::MatrixXd::Ones(12, 3));
  EXPECT_EQ(matrix.coeff(3, 0), 1.0);
  EXPECT_THROW(pattern.add_block(matrix, 2, 2, Eigen::MatrixXd::Zero(30, 30)), std::logic_error);
  EXPECT_THROW(CellBlockPattern(offsets, {{1, 2}}, {0, 0, 1}), std::logic_error);
}

}  // namespace
}  // namespace altfem::dg
