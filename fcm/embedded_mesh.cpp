#include "fcm/embedded_mesh.hpp"

#include <array>
#include <map>
#include <vector>

#include "shared/common/error.hpp"
#include "shared/mesh/tetrahedra_of_hexahedra.hpp"
#include "shared/scene/tetrahedralize_geometry.hpp"

namespace altfem::fcm {

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

VolumeMesh embedded_tetrahedra(const SceneGeometry& geometry, double max_cell_size, const std::string& scene_file) {
  if (geometry.mesh) {
    if (element_shape(geometry.mesh->element_type) == ElementShape::hexahedron) {
      try {
        return weld_coincident_nodes(tetrahedra_of_hexahedra(*geometry.mesh));
      } catch (const InputError& error) {
        throw InputError(input_message(scene_file, "/geometry/mesh", error.what()));
      }
    }
    return weld_coincident_nodes(VolumeMesh{ElementType::tet4, geometry.mesh->nodes, geometry.mesh->cells.leftCols(4)});
  }
  return tetrahedralize_geometry(geometry, max_cell_size, "/discretization/fcm/embedded_cell_size");
}

}  // namespace altfem::fcm
