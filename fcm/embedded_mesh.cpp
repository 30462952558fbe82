#include "fcm/embedded_mesh.hpp"

#include "shared/common/error.hpp"
#include "shared/mesh/tetrahedra_of_hexahedra.hpp"
#include "shared/mesh/weld_coincident_nodes.hpp"
#include "shared/scene/tetrahedralize_geometry.hpp"

namespace altfem::fcm {

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
