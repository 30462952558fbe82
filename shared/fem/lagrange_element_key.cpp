#include "shared/fem/lagrange_element_key.hpp"

#include <algorithm>

#include "shared/io/binary_cache.hpp"

namespace altfem {

std::uint64_t lagrange_element_key(const VolumeMesh& mesh, const NodeConstraints* constraints, int cell) {
  CacheKeyHasher hasher;
  hasher.scalar<std::int32_t>(static_cast<std::int32_t>(mesh.element_type));
  const Eigen::Index count = mesh.cells.cols();
  for (Eigen::Index a = 0; a < count; ++a) hasher.matrix(mesh.nodes.row(mesh.cells(cell, a)).eval());
  // The functions met in the order substitute meets them: the cell's nodes, then each
  // hanging node's masters; each hashed by the place it was first met.
  std::vector<int> met;
  const auto place = [&met](int function) {
    const auto found = std::find(met.begin(), met.end(), function);
    if (found != met.end()) return static_cast<std::int32_t>(found - met.begin());
    met.push_back(function);
    return static_cast<std::int32_t>(met.size() - 1);
  };
  for (Eigen::Index a = 0; a < count; ++a) hasher.scalar(place(mesh.cells(cell, a)));
  if (constraints && !constraints->empty())
    for (Eigen::Index a = 0; a < count; ++a) {
      const int node = mesh.cells(cell, a);
      if (node < constraints->free_nodes) continue;
      const int hanging = node - constraints->free_nodes;
      hasher.scalar<std::int32_t>(static_cast<std::int32_t>(a));
      for (std::size_t k = 0; k < constraints->masters[hanging].size(); ++k) {
        hasher.scalar(place(constraints->masters[hanging][k]));
        hasher.scalar(constraints->weights[hanging][k]);
      }
    }
  return hasher.value();
}

void lagrange_element_functions(const VolumeMesh& mesh, const NodeConstraints* constraints, int cell,
                                std::vector<int>& functions) {
  functions.resize(static_cast<std::size_t>(mesh.cells.cols()));
  for (Eigen::Index a = 0; a < mesh.cells.cols(); ++a) functions[a] = mesh.cells(cell, a);
  if (!constraints) return;
  std::vector<double> values(functions.size(), 0.0);
  constraints->substitute(functions, values);
}

}  // namespace altfem
