#include "shared/cut_cells/kept_hanging_nodes.hpp"

#include <string>
#include <unordered_map>

#include "shared/common/error.hpp"

namespace altfem {

KeptHangingNodes kept_hanging_nodes(const std::vector<int>& background_node, const NodeConstraints& background) {
  const int kept = static_cast<int>(background_node.size());
  std::unordered_map<int, std::vector<int>> copies;  // background node → its kept nodes
  for (int node = 0; node < kept; ++node) copies[background_node[node]].push_back(node);

  // Per kept node, its masters among the kept nodes (empty: free).
  std::vector<std::vector<int>> masters(static_cast<std::size_t>(kept));
  std::vector<int> hanging_index(static_cast<std::size_t>(kept), -1);  // into background.masters
  for (int node = 0; node < kept; ++node) {
    const int hanging = background_node[node] - background.free_nodes;
    if (hanging < 0) continue;
    std::vector<int> kept_masters;
    for (const int master : background.masters[hanging]) {
      const auto found = copies.find(master);
      if (found == copies.end()) {
        kept_masters.clear();
        break;
      }
      if (found->second.size() > 1)
        throw NumericalError("fcm: a hanging node at the background node " + std::to_string(background_node[node]) +
                             " hangs on a node with " + std::to_string(found->second.size()) +
                             " copies (the material splits where the refinement changes level)");
      kept_masters.push_back(found->second.front());
    }
    if (kept_masters.empty()) continue;
    masters[node] = std::move(kept_masters);
    hanging_index[node] = hanging;
  }

  KeptHangingNodes result;
  result.new_index.assign(static_cast<std::size_t>(kept), -1);
  int next = 0;
  for (int node = 0; node < kept; ++node)
    if (masters[node].empty()) result.new_index[node] = next++;
  result.constraints.free_nodes = next;
  for (int node = 0; node < kept; ++node) {
    if (masters[node].empty()) continue;
    result.new_index[node] = next++;
    for (int& master : masters[node]) master = result.new_index[master];
    result.constraints.masters.push_back(std::move(masters[node]));
    result.constraints.weights.push_back(background.weights[hanging_index[node]]);
  }
  return result;
}

}  // namespace altfem
