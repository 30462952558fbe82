#pragma once
// Which rows of a distributed matrix each rank holds (issue #37; docs/scaling.md): METIS's
// parts of the matrix's own graph, so that a rank's rows couple mostly to its own rows and
// few entries cross ranks, numbered part after part so that each rank's rows are one
// contiguous range, as PETSc's MPIAIJ wants.
#include <Eigen/SparseCore>
#include <vector>

namespace altfem {

/// The blocks (of `block` DOFs, columns b·block … b·block + block − 1) of a square pattern
/// grouped by equal columns, the same rows: a dg cell's functions couple to exactly the
/// same DOFs, so a partition of the groups never divides a cell (whose functions GAMG
/// would then aggregate across ranks' boundaries). Returns each block's group (#blocks);
/// `groups` receives their count. Groups are numbered in no particular order.
std::vector<int> equal_column_groups(const Eigen::SparseMatrix<double>& matrix, int block, int& groups);

struct PartitionedRows {
  long long first_row = 0, last_row = 0;  ///< this rank's rows in the new numbering: [first, last)
  std::vector<long long> new_of_old;      ///< #rows: each row's new index
  std::vector<long long> old_of_new;      ///< #rows: the inverse permutation
};

/// METIS's partition (graph_partition.hpp, rank 0's, the same on every rank) of the graph
/// of `matrix`'s equal-column groups, each weighted by its blocks, into ranks::count()
/// parts; rows renumbered part by part, in their old order within a part, blocks kept whole.
PartitionedRows partitioned_rows(const Eigen::SparseMatrix<double>& matrix, int block);

}  // namespace altfem
