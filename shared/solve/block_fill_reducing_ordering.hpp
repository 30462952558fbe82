#pragma once
// Fill-reducing orderings of block-structured sparse matrices. Vector-valued
// problems number their unknowns node by node (3 per node in 3D elasticity), so
// the scalar matrix is the node graph with every vertex blown up into a dense
// b × b block. Ordering the node graph (b² times fewer edges) and expanding
// each node into its b consecutive unknowns is faster than ordering the scalar
// matrix and keeps each node's unknowns adjacent, which CHOLMOD's supernodes
// then cover whole (Ashcraft 1995, "Compressed graphs and the minimum degree
// algorithm").
#include <Eigen/SparseCore>

#include <vector>

namespace altfem {

/// The largest b in {3, 2} such that `matrix` (square, compressed, both
/// triangles) consists of dense b × b blocks: rows and columns come in
/// aligned groups of b with identical patterns. Returns 1 when there is none.
int sparsity_block_size(const Eigen::SparseMatrix<double>& matrix);

/// A fill-reducing permutation of `matrix`'s unknowns (#rows; entry k is the
/// unknown eliminated k-th) computed on its graph of b × b blocks, b =
/// `block_size` as returned by sparsity_block_size. CHOLMOD computes both an
/// approximate minimum degree and a METIS nested dissection ordering of the block
/// graph and keeps the one whose factor has fewer entries (CHOLMOD's criterion).
std::vector<int> block_fill_reducing_ordering(const Eigen::SparseMatrix<double>& matrix, int block_size);

}  // namespace altfem
