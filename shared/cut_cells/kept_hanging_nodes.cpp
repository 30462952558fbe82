#include "shared/cut_cells/kept_hanging_nodes.hpp"

#include <algorithm>
#include <string>
#include <unordered_map>

#include "shared/common/error.hpp"

namespace altfem {

namespace {

// Whether kept cells `first` and `second` hold a node in common.
bool share_a_node(const Eigen::MatrixXi& cells, int first, int second) {
  for (Eigen::Index a = 0; a < cells.cols(); ++a)
    if ((cells.row(second).array() == cells(first, a)).any()) return true;
  return false;
}

}  // namespace

KeptHangingNodes kept_hanging_nodes(const std::vector<int>& background_node, int grid_free_nodes,
                                    const HangingNodeSources& sources, const Eigen::MatrixXi& cells,
                                    const std::vector<int>& cell_leaf) {
  const int kept = static_cast<int>(background_node.size());
  std::unordered_map<int, std::vector<int>> leaf_cells;  // grid leaf → its kept cells (pieces)
  for (int cell = 0; cell < static_cast<int>(cell_leaf.size()); ++cell) leaf_cells[cell_leaf[cell]].push_back(cell);
  std::vector<std::vector<int>> node_cells(static_cast<std::size_t>(kept));  // kept node → the kept cells holding it
  for (Eigen::Index cell = 0; cell < cells.rows(); ++cell)
    for (Eigen::Index a = 0; a < cells.cols(); ++a) node_cells[cells(cell, a)].push_back(static_cast<int>(cell));

  // Per kept node, its source leaf's nodes among the kept nodes, some possibly hanging (empty: free).
  DirectConstraints direct(static_cast<std::size_t>(kept));
  for (int node = 0; node < kept; ++node) {
    const int hanging = background_node[node] - grid_free_nodes;
    if (hanging < 0) continue;
    const auto& candidates = sources[hanging];
    const auto source = std::find_if(candidates.begin(), candidates.end(), [&](const HangingNodeSource& candidate) {
      return leaf_cells.count(candidate.leaf) > 0;
    });
    if (source == candidates.end()) continue;
    // The leaf's piece the material continues into from the hanging node's cells: the one
    // that shares a node copy with them (the star of a node joins the pieces that meet).
    std::vector<int> pieces = leaf_cells.at(source->leaf);
    if (pieces.size() > 1) {
      std::erase_if(pieces, [&](int piece) {
        return std::none_of(node_cells[node].begin(), node_cells[node].end(),
                            [&](int cell) { return share_a_node(cells, cell, piece); });
      });
      if (pieces.size() != 1)
        throw NumericalError("fcm: the hanging node at the background node " + std::to_string(background_node[node]) +
                             " lies on a coarser cell of " + std::to_string(leaf_cells.at(source->leaf).size()) +
                             " pieces, and " + std::to_string(pieces.size()) +
                             " of them meet its cells (which one it continues is not decided)");
    }
    for (std::size_t k = 0; k < source->masters.size(); ++k) {
      // The piece holds a copy of every node of its leaf.
      Eigen::Index a = 0;
      while (background_node[cells(pieces.front(), a)] != source->masters[k]) ++a;
      direct[node].emplace_back(cells(pieces.front(), a), source->weights[k]);
    }
  }

  KeptHangingNodes result;
  result.constraints = resolve_constraints(direct, result.new_index);
  return result;
}

}  // namespace altfem
