#include "shared/cut_cells/kept_hanging_nodes.hpp"

#include <algorithm>
#include <string>
#include <unordered_map>

#include "shared/common/error.hpp"

namespace altfem {

KeptHangingNodes kept_hanging_nodes(const std::vector<int>& background_node, int grid_free_nodes,
                                    const HangingNodeSources& sources, const std::vector<char>& kept_leaf) {
  const int kept = static_cast<int>(background_node.size());
  std::unordered_map<int, std::vector<int>> copies;  // grid node → its kept nodes
  for (int node = 0; node < kept; ++node) copies[background_node[node]].push_back(node);

  // Per kept node, its source leaf's nodes among the kept nodes, some possibly hanging (empty: free).
  DirectConstraints direct(static_cast<std::size_t>(kept));
  for (int node = 0; node < kept; ++node) {
    const int hanging = background_node[node] - grid_free_nodes;
    if (hanging < 0) continue;
    const auto& candidates = sources[hanging];
    const auto source = std::find_if(candidates.begin(), candidates.end(),
                                     [&](const HangingNodeSource& candidate) { return kept_leaf[candidate.leaf]; });
    if (source == candidates.end()) continue;
    for (std::size_t k = 0; k < source->masters.size(); ++k) {
      // A kept leaf's cells (pieces) hold a copy of every node of the leaf.
      const std::vector<int>& master_copies = copies.at(source->masters[k]);
      if (master_copies.size() > 1)
        throw NumericalError("fcm: a hanging node at the background node " + std::to_string(background_node[node]) +
                             " hangs on a node with " + std::to_string(master_copies.size()) +
                             " copies (the material splits where the refinement changes level)");
      direct[node].emplace_back(master_copies.front(), source->weights[k]);
    }
  }

  KeptHangingNodes result;
  result.constraints = resolve_constraints(direct, result.new_index);
  return result;
}

}  // namespace altfem
