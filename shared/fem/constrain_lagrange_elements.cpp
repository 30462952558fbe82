#include "shared/fem/constrain_lagrange_elements.hpp"

#include <algorithm>

namespace altfem {

void substitute_hanging(std::span<const int> nodes, const NodeConstraints& constraints, std::vector<int>& basis,
                        Eigen::MatrixXd& substitution) {
  basis.clear();
  const auto column = [&](int node) {
    const auto found = std::find(basis.begin(), basis.end(), node);
    if (found != basis.end()) return static_cast<int>(found - basis.begin());
    basis.push_back(node);
    return static_cast<int>(basis.size()) - 1;
  };
  for (const int node : nodes)
    if (node < constraints.free_nodes) column(node);
  for (const int node : nodes)
    if (node >= constraints.free_nodes)
      for (const int master : constraints.masters[node - constraints.free_nodes]) column(master);
  substitution.setZero(static_cast<Eigen::Index>(nodes.size()), static_cast<Eigen::Index>(basis.size()));
  for (std::size_t a = 0; a < nodes.size(); ++a) {
    const int node = nodes[a];
    if (node < constraints.free_nodes) {
      substitution(static_cast<Eigen::Index>(a), column(node)) = 1;
      continue;
    }
    const int hanging = node - constraints.free_nodes;
    for (std::size_t k = 0; k < constraints.masters[hanging].size(); ++k)
      substitution(static_cast<Eigen::Index>(a), column(constraints.masters[hanging][k])) +=
          constraints.weights[hanging][k];
  }
}

bool any_hanging(std::span<const int> nodes, const NodeConstraints& constraints) {
  return std::any_of(nodes.begin(), nodes.end(), [&](int node) { return node >= constraints.free_nodes; });
}

ElementMasses constrain_element_masses(const ElementMasses& masses, const Eigen::MatrixXi& cells,
                                       const NodeConstraints& constraints) {
  ElementMasses constrained = masses;
  std::vector<int> nodes, basis;
  Eigen::MatrixXd substitution;
  for (int e = 0; e < masses.size(); ++e) {
    nodes.assign(cells.row(e).begin(), cells.row(e).end());
    if (!any_hanging(nodes, constraints)) continue;
    substitute_hanging(nodes, constraints, basis, substitution);
    constrained.matrices[e] = substitution.transpose() * masses.matrices[e] * substitution;
    constrained.integrals[e] = substitution.transpose() * masses.integrals[e];
  }
  return constrained;
}

}  // namespace altfem
