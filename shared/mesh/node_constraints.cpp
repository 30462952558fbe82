#include "shared/mesh/node_constraints.hpp"

#include <algorithm>
#include <cstddef>
#include <unordered_map>

namespace altfem {

void NodeConstraints::substitute(std::vector<int>& basis, std::vector<double>& values) const {
  if (empty()) return;
  const std::size_t count = basis.size();
  for (std::size_t a = 0; a < count; ++a) {
    if (basis[a] < free_nodes) continue;
    const int hanging = basis[a] - free_nodes;
    const double value = values[a];
    values[a] = 0;  // the hanging node's slot stays, emptied, until compacted below
    for (std::size_t k = 0; k < masters[hanging].size(); ++k) {
      const int master = masters[hanging][k];
      const auto found = std::find(basis.begin(), basis.end(), master);
      if (found != basis.end()) values[found - basis.begin()] += weights[hanging][k] * value;
      else {
        basis.push_back(master);
        values.push_back(weights[hanging][k] * value);
      }
    }
  }
  std::size_t kept = 0;
  for (std::size_t a = 0; a < basis.size(); ++a)
    if (basis[a] < free_nodes) {
      basis[kept] = basis[a];
      values[kept++] = values[a];
    }
  basis.resize(kept);
  values.resize(kept);
}

Eigen::VectorXd NodeConstraints::all_nodes(const Eigen::VectorXd& u) const {
  Eigen::VectorXd all(3 * (static_cast<Eigen::Index>(free_nodes) + hanging_nodes()));
  all.head(u.size()) = u;
  for (int i = 0; i < hanging_nodes(); ++i) {
    Eigen::Vector3d value = Eigen::Vector3d::Zero();
    for (std::size_t k = 0; k < masters[i].size(); ++k) value += weights[i][k] * u.segment<3>(3 * masters[i][k]);
    all.segment<3>(3 * (static_cast<Eigen::Index>(free_nodes) + i)) = value;
  }
  return all;
}

NodeConstraints resolve_constraints(const DirectConstraints& direct, std::vector<int>& new_index) {
  const int node_count = static_cast<int>(direct.size());
  DirectConstraints resolved(direct.size());
  std::vector<char> done(direct.size(), 0);
  const auto resolve = [&](auto&& self, int node) -> const std::vector<std::pair<int, double>>& {
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

  NodeConstraints constraints;
  new_index.assign(direct.size(), -1);
  int next = 0;
  for (int node = 0; node < node_count; ++node)
    if (direct[node].empty()) new_index[node] = next++;
  constraints.free_nodes = next;
  for (int node = 0; node < node_count; ++node)
    if (!direct[node].empty()) new_index[node] = next++;
  for (int node = 0; node < node_count; ++node) {
    if (direct[node].empty()) continue;
    std::vector<int>& masters = constraints.masters.emplace_back();
    std::vector<double>& weights = constraints.weights.emplace_back();
    for (const auto& [master, weight] : resolve(resolve, node)) {
      masters.push_back(new_index[master]);
      weights.push_back(weight);
    }
  }
  return constraints;
}

}  // namespace altfem
