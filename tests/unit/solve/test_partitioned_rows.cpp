// Which rows each rank holds (partitioned_rows.hpp): functions with equal columns, a dg
// cell's, form one group, functions of different cells never do; on one process the
// numbering is the method's own.
#include <gtest/gtest.h>

#include <vector>

#include "shared/solve/partitioned_rows.hpp"

namespace altfem {
namespace {

// A dg-like pattern with block size 3: `cells` cells in a row, each with `functions`
// functions, a cell coupled to itself and its neighbours in the row.
Eigen::SparseMatrix<double> chain_of_cells(int cells, int functions) {
  const int dofs = 3 * cells * functions;
  std::vector<Eigen::Triplet<double>> entries;
  for (int column = 0; column < dofs; ++column) {
    const int cell = column / (3 * functions);
    for (int other = std::max(cell - 1, 0); other <= std::min(cell + 1, cells - 1); ++other)
      for (int row = 3 * functions * other; row < 3 * functions * (other + 1); ++row)
        entries.emplace_back(row, column, 1.0);
  }
  Eigen::SparseMatrix<double> matrix(dofs, dofs);
  matrix.setFromTriplets(entries.begin(), entries.end());
  return matrix;
}

TEST(PartitionedRows, FunctionsOfOneCellShareAGroupAndCellsDoNot) {
  const int cells = 5, functions = 4;
  int groups = 0;
  const std::vector<int> group = equal_column_groups(chain_of_cells(cells, functions), 3, groups);
  ASSERT_EQ(group.size(), static_cast<size_t>(cells * functions));
  EXPECT_EQ(groups, cells);
  for (int cell = 0; cell < cells; ++cell)
    for (int function = 0; function < functions; ++function) {
      EXPECT_EQ(group[cell * functions + function], group[cell * functions]) << "cell " << cell;
      if (cell > 0) EXPECT_NE(group[cell * functions], group[(cell - 1) * functions]) << "cell " << cell;
    }
}

TEST(PartitionedRows, NodesWithTheirOwnColumnsAreGroupsOfOne) {
  // One function per cell of the chain: every column differs (the ends from the middle).
  int groups = 0;
  equal_column_groups(chain_of_cells(6, 1), 3, groups);
  EXPECT_EQ(groups, 6);
}

TEST(PartitionedRows, OneProcessKeepsTheMethodsNumbering) {
  const Eigen::SparseMatrix<double> matrix = chain_of_cells(4, 3);
  const PartitionedRows rows = partitioned_rows(matrix, 3);
  EXPECT_EQ(rows.first_row, 0);
  EXPECT_EQ(rows.last_row, matrix.rows());
  for (long long row = 0; row < matrix.rows(); ++row) {
    EXPECT_EQ(rows.new_of_old[row], row);
    EXPECT_EQ(rows.old_of_new[row], row);
  }
}

}  // namespace
}  // namespace altfem
