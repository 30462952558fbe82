#include "shared/fem/constrain_lagrange_elements.hpp"

#include <algorithm>

namespace altfem {

TabulatedElements constrain_lagrange_elements(const TabulatedElements& elements, const NodeConstraints& constraints) {
  TabulatedElements constrained;
  std::vector<int> basis;
  Eigen::MatrixXd substitution, values, gradients;  // reused across elements
  for (int e = 0; e < elements.size(); ++e) {
    const ElementView element = elements[e];
    const int local = element.basis_count(), points = element.point_count();
    const bool any_hanging = std::any_of(element.basis.begin(), element.basis.end(),
                                         [&](int node) { return node >= constraints.free_nodes; });
    if (!any_hanging) {
      const Eigen::Map<const Eigen::MatrixXd> raw_gradients(element.gradients, 3, Eigen::Index(points) * local);
      constrained.add(element.basis, element.weights, element.values, raw_gradients.transpose(), element.material);
      continue;
    }
    // substitution (local × new): column j is the new function basis[j] in the old ones.
    basis.clear();
    const auto column = [&](int node) {
      const auto found = std::find(basis.begin(), basis.end(), node);
      if (found != basis.end()) return static_cast<int>(found - basis.begin());
      basis.push_back(node);
      return static_cast<int>(basis.size()) - 1;
    };
    for (const int node : element.basis)
      if (node < constraints.free_nodes) column(node);
    for (const int node : element.basis)
      if (node >= constraints.free_nodes)
        for (const int master : constraints.masters[node - constraints.free_nodes]) column(master);
    substitution.setZero(local, static_cast<Eigen::Index>(basis.size()));
    for (int a = 0; a < local; ++a) {
      const int node = element.basis[a];
      if (node < constraints.free_nodes) {
        substitution(a, column(node)) = 1;
        continue;
      }
      const int hanging = node - constraints.free_nodes;
      for (std::size_t k = 0; k < constraints.masters[hanging].size(); ++k)
        substitution(a, column(constraints.masters[hanging][k])) += constraints.weights[hanging][k];
    }
    values = element.values * substitution;
    gradients.resize(Eigen::Index(points) * substitution.cols(), 3);
    for (int q = 0; q < points; ++q)
      gradients.middleRows(Eigen::Index(q) * substitution.cols(), substitution.cols()) =
          substitution.transpose() * element.gradients_at(q);
    constrained.add(basis, element.weights, values, gradients, element.material);
  }
  return constrained;
}

}  // namespace altfem
