#include "shared/cut_cells/kept_hanging_nodes.hpp"

#include <algorithm>
#include <string>
#include <unordered_map>
#include <utility>

#include "shared/common/error.hpp"

namespace altfem {

KeptHangingNodes kept_hanging_nodes(const std::vector<int>& background_node, int grid_free_nodes,
                                    const HangingNodeSources& sources, const std::vector<char>& kept_leaf) {
  const int kept = static_cast<int>(background_node.size());
  std::unordered_map<int, std::vector<int>> copies;  // grid node → its kept nodes
  for (int node = 0; node < kept; ++node) copies[background_node[node]].push_back(node);

  // Per kept node, its source leaf's nodes among the kept nodes, some possibly hanging (empty: free).
  using Terms = std::vector<std::pair<int, double>>;
  std::vector<Terms> direct(static_cast<std::size_t>(kept));
  for (int node = 0; node < kept; ++node) {
    const int hanging = background_node[node] - grid_free_nodes;
    if (hanging < 0) continue;
    const auto& candidates = sources[hanging];
    const auto source = std::find_if(candidates.begin(), candidates.end(),
                                     [&](const HangingNodeSource& candidate) { return kept_leaf[candidate.leaf]; });
    if (source == candidates.end()) continue;
    Terms terms;
    for (std::size_t k = 0; k < source->masters.size(); ++k) {
      const auto found = copies.find(source->masters[k]);
      if (found == copies.end()) {
        terms.clear();
        break;
      }
      if (found->second.size() > 1)
        throw NumericalError("fcm: a hanging node at the background node " + std::to_string(background_node[node]) +
                             " hangs on a node with " + std::to_string(found->second.size()) +
                             " copies (the material splits where the refinement changes level)");
      terms.emplace_back(found->second.front(), source->weights[k]);
    }
    direct[node] = std::move(terms);
  }

  // Hanging masters substituted by theirs (a chain climbs one level per step under 2:1 balance).
  std::vector<Terms> resolved(static_cast<std::size_t>(kept));
  std::vector<char> done(static_cast<std::size_t>(kept), 0);
  const auto resolve = [&](auto&& self, int node) -> const Terms& {
    if (done[node]) return resolved[node];
    std::unordered_map<int, double> sum;
    for (const auto& [master, weight] : direct[node]) {
      if (direct[master].empty()) sum[master] += weight;
      else
        for (const auto& [free, inner] : self(self, master)) sum[free] += weight * inner;
    }
    resolved[node].assign(sum.begin(), sum.end());
    done[node] = 1;
    return resolved[node];
  };

  KeptHangingNodes result;
  result.new_index.assign(static_cast<std::size_t>(kept), -1);
  int next = 0;
  for (int node = 0; node < kept; ++node)
    if (direct[node].empty()) result.new_index[node] = next++;
  result.constraints.free_nodes = next;
  for (int node = 0; node < kept; ++node) {
    if (direct[node].empty()) continue;
    result.new_index[node] = next++;
    std::vector<int>& masters = result.constraints.masters.emplace_back();
    std::vector<double>& weights = result.constraints.weights.emplace_back();
    for (const auto& [master, weight] : resolve(resolve, node)) {
      masters.push_back(master);
      weights.push_back(weight);
    }
  }
  for (std::vector<int>& masters : result.constraints.masters)
    for (int& master : masters) master = result.new_index[master];
  return result;
}

}  // namespace altfem
