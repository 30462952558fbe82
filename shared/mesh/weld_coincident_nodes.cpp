#include "shared/mesh/weld_coincident_nodes.hpp"

#include <array>
#include <map>
#include <vector>

namespace altfem {

VolumeMesh weld_coincident_nodes(const VolumeMesh& mesh) {
  std::map<std::array<double, 3>, int> first_at;
  std::vector<int> welded(static_cast<std::size_t>(mesh.nodes.rows()));
  std::vector<Eigen::Index> kept;
  for (Eigen::Index node = 0; node < mesh.nodes.rows(); ++node) {
    const auto [entry, added] =
        first_at.emplace(std::array<double, 3>{mesh.nodes(node, 0), mesh.nodes(node, 1), mesh.nodes(node, 2)},
                         static_cast<int>(kept.size()));
    if (added) kept.push_back(node);
    welded[node] = entry->second;
  }
  VolumeMesh result{mesh.element_type, mesh.nodes(kept, Eigen::all), mesh.cells};
  for (Eigen::Index cell = 0; cell < result.cells.rows(); ++cell)
    for (Eigen::Index k = 0; k < result.cells.cols(); ++k) result.cells(cell, k) = welded[result.cells(cell, k)];
  return result;
}

}  // namespace altfem
