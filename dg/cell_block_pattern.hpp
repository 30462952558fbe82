#pragma once
// The sparsity of a DG matrix by whole cell blocks (Kaufmann et al. 2009 §4: K = Σ_K K_K
// + Σ_f K_f couples a cell's functions with its own and with those of the cells it shares
// a face with), built once from the cell adjacency, so that element and face blocks are
// added into the compressed matrix's values in place: no triplets, no sort, no merge of
// duplicates. Zeros are stored: every coupled pair of cells holds its whole block, so an
// element's 3n coefficients share one row pattern and the direct solver orders elements,
// not coefficients (shared/solve/block_fill_reducing_ordering.hpp).
#include <Eigen/SparseCore>
#include <array>
#include <vector>

namespace altfem::dg {

class CellBlockPattern {
public:
  /// offsets: #cells + 1, cell c's functions are [offsets[c], offsets[c + 1]), its DOFs
  /// 3a + i; couplings: the pairs of cells that share a face (either order, repeats and
  /// pairs of a cell with itself allowed). diagonal_only (#cells, or empty for none): cells
  /// whose columns hold their own diagonal entries alone, no block (one rank's share of K
  /// leaves the cells of other ranks that none of its faces touches so: docs/scaling.md);
  /// they must be in no coupling, and no block is added for them.
  CellBlockPattern(std::vector<int> offsets, const std::vector<std::array<int, 2>>& couplings,
                   std::vector<char> diagonal_only = {});

  /// Makes `matrix` #dofs square, compressed, column-major, every coupled block present
  /// with zero values (in place: a returned matrix would be copied, Eigen's sparse
  /// assignment does not move).
  void make_zero_matrix(Eigen::SparseMatrix<double>& matrix) const;

  /// matrix (from make_zero_matrix) += `block` at rows of row_cell's DOFs, columns of
  /// column_cell's DOFs. block: 3 n_row × 3 n_column; the two cells must be coupled
  /// (or equal).
  void add_block(Eigen::SparseMatrix<double>& matrix, int row_cell, int column_cell,
                 const Eigen::Ref<const Eigen::MatrixXd>& block) const;

private:
  std::vector<int> offsets_;
  std::vector<char> diagonal_only_;   // #cells or empty
  std::vector<int> first_neighbour_;  // #cells + 1, into neighbours_ and row_starts_
  std::vector<int> neighbours_;       // per cell, the coupled cells (itself included), ascending
  std::vector<int> row_starts_;       // per neighbour, the position of its first row in the column
};

}  // namespace altfem::dg
