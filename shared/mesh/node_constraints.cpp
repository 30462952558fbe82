#include "shared/mesh/node_constraints.hpp"

#include <algorithm>
#include <cstddef>

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

}  // namespace altfem
