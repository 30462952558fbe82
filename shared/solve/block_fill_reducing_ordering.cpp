#include "shared/solve/block_fill_reducing_ordering.hpp"

#include "shared/common/error.hpp"

#include <cholmod.h>

namespace altfem {
namespace {

// Whether every column's row indices come in runs of `block_size` aligned to
// multiples of it, and the columns of each block share one pattern.
bool has_block_structure(const Eigen::SparseMatrix<double>& matrix, int block_size) {
  if (matrix.rows() % block_size != 0) return false;
  const int* starts = matrix.outerIndexPtr();
  const int* rows = matrix.innerIndexPtr();
  for (int column = 0; column < matrix.cols(); ++column) {
    const int first_column = column - column % block_size;
    const int count = starts[column + 1] - starts[column];
    if (count % block_size != 0 || count != starts[first_column + 1] - starts[first_column]) return false;
    for (int k = 0; k < count; ++k) {
      const int row = rows[starts[column] + k];
      if (row != rows[starts[first_column] + k] || row % block_size != k % block_size) return false;
    }
  }
  return true;
}

}  // namespace

int sparsity_block_size(const Eigen::SparseMatrix<double>& matrix) {
  for (int block_size : {3, 2})
    if (has_block_structure(matrix, block_size)) return block_size;
  return 1;
}

std::vector<int> block_fill_reducing_ordering(const Eigen::SparseMatrix<double>& matrix, int block_size) {
  const int node_count = static_cast<int>(matrix.rows()) / block_size;
  cholmod_common common;
  cholmod_start(&common);
  common.print = 0;
  common.supernodal = CHOLMOD_SIMPLICIAL;  // only the ordering is wanted, not a supernodal structure
  common.nmethods = 2;
  common.method[0].ordering = CHOLMOD_AMD;
  common.method[1].ordering = CHOLMOD_METIS;

  // The block graph's upper triangle (stype 1), one column per node, built from
  // the first column of each block.
  std::vector<int> column_starts(node_count + 1, 0);
  std::vector<int> node_rows;
  node_rows.reserve(static_cast<std::size_t>(matrix.nonZeros() / (block_size * block_size) + node_count));
  for (int node = 0; node < node_count; ++node) {
    for (Eigen::SparseMatrix<double>::InnerIterator entry(matrix, node * block_size); entry; ++entry) {
      const int row = static_cast<int>(entry.row());
      if (row % block_size == 0 && row / block_size <= node) node_rows.push_back(row / block_size);
    }
    column_starts[node + 1] = static_cast<int>(node_rows.size());
  }
  cholmod_sparse graph{};
  graph.nrow = graph.ncol = static_cast<std::size_t>(node_count);
  graph.nzmax = node_rows.size();
  graph.p = column_starts.data();
  graph.i = node_rows.data();
  graph.stype = 1;
  graph.itype = CHOLMOD_INT;
  graph.xtype = CHOLMOD_PATTERN;
  graph.dtype = CHOLMOD_DOUBLE;
  graph.sorted = 1;
  graph.packed = 1;

  cholmod_factor* symbolic = cholmod_analyze(&graph, &common);
  if (symbolic == nullptr) {
    const int status = common.status;
    cholmod_finish(&common);
    throw NumericalError("CHOLMOD could not order the block graph (CHOLMOD status " + std::to_string(status) + ")");
  }
  const int* node_order = static_cast<const int*>(symbolic->Perm);
  std::vector<int> order(matrix.rows());
  for (int k = 0; k < node_count; ++k)
    for (int component = 0; component < block_size; ++component)
      order[k * block_size + component] = node_order[k] * block_size + component;
  cholmod_free_factor(&symbolic, &common);
  cholmod_finish(&common);
  return order;
}

}  // namespace altfem
