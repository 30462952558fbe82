#include "shared/solve/block_fill_reducing_ordering.hpp"

#include <cholmod.h>

#include <algorithm>

#include "shared/common/error.hpp"

namespace altfem {

namespace {

constexpr int small_graph_groups = 500;

}  // namespace

std::vector<int> supervariable_starts(const Eigen::SparseMatrix<double>& matrix) {
  const int* starts = matrix.outerIndexPtr();
  const int* rows = matrix.innerIndexPtr();
  std::vector<int> runs{0};
  for (int column = 1; column < matrix.cols(); ++column) {
    const bool same =
        std::equal(rows + starts[column], rows + starts[column + 1], rows + starts[column - 1], rows + starts[column]);
    if (!same) runs.push_back(column);
  }
  runs.push_back(static_cast<int>(matrix.cols()));
  return runs;
}

std::vector<int> block_fill_reducing_ordering(const Eigen::SparseMatrix<double>& matrix) {
  const std::vector<int> runs = supervariable_starts(matrix);
  const int group_count = static_cast<int>(runs.size()) - 1;
  std::vector<int> group_of(matrix.rows());
  for (int group = 0; group < group_count; ++group)
    std::fill(group_of.begin() + runs[group], group_of.begin() + runs[group + 1], group);

  // The group graph's upper triangle (stype 1), one column per group, built from the
  // group's first column: its rows are sorted, so a group's rows are consecutive.
  std::vector<int> column_starts(group_count + 1, 0);
  std::vector<int> group_rows;
  group_rows.reserve(static_cast<std::size_t>(group_count) * 8);
  for (int group = 0; group < group_count; ++group) {
    for (Eigen::SparseMatrix<double>::InnerIterator entry(matrix, runs[group]); entry; ++entry) {
      const int row_group = group_of[entry.row()];
      if (row_group <= group &&
          (group_rows.size() == static_cast<std::size_t>(column_starts[group]) || group_rows.back() != row_group))
        group_rows.push_back(row_group);
    }
    column_starts[group + 1] = static_cast<int>(group_rows.size());
  }

  cholmod_common common;
  cholmod_start(&common);
  common.print = 0;
  common.supernodal = CHOLMOD_SIMPLICIAL;  // only the ordering is wanted, not a supernodal structure
  // A graph of a few hundred groups (the coarsest grid of a multilevel cycle) is ordered by
  // AMD alone: nested dissection's METIS calls would cost more than the factorisation saves.
  common.nmethods = group_count < small_graph_groups ? 1 : 2;
  common.method[0].ordering = CHOLMOD_AMD;
  common.method[1].ordering = CHOLMOD_NESDIS;
  cholmod_sparse graph{};
  graph.nrow = graph.ncol = static_cast<std::size_t>(group_count);
  graph.nzmax = group_rows.size();
  graph.p = column_starts.data();
  graph.i = group_rows.data();
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
    throw NumericalError("CHOLMOD could not order the supervariable graph (CHOLMOD status " + std::to_string(status) +
                         ")");
  }
  const int* group_order = static_cast<const int*>(symbolic->Perm);
  std::vector<int> order;
  order.reserve(matrix.rows());
  for (int k = 0; k < group_count; ++k)
    for (int unknown = runs[group_order[k]]; unknown < runs[group_order[k] + 1]; ++unknown) order.push_back(unknown);
  cholmod_free_factor(&symbolic, &common);
  cholmod_finish(&common);
  return order;
}

}  // namespace altfem
