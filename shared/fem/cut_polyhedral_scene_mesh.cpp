#include "shared/fem/cut_polyhedral_scene_mesh.hpp"

#include "shared/mesh/cut_polyhedral_mesh.hpp"

namespace altfem {

PolyhedralSceneMesh cut_polyhedral_scene_mesh(const PolyhedralSceneMesh& mesh, const CuttingPlane& blade,
                                              nlohmann::json& facts) {
  PolyhedralCut cut = cut_polyhedral_mesh(mesh.sliced.mesh, blade);
  facts = {{"crossed_cells", cut.crossed_cells},     {"joined_cells", cut.joined_cells},
           {"separated_faces", cut.separated_faces}, {"duplicated_nodes", cut.duplicated_nodes},
           {"snapped_nodes", cut.snapped_nodes},     {"cells", cut.mesh.cell_count()}};
  PolyhedralSceneMesh result = mesh;
  result.sliced.mesh = std::move(cut.mesh);
  result.converted.reset();
  result.node_sources = std::move(cut.node_sources);
  return result;
}

std::shared_ptr<const MethodMesh> cut_handed_polyhedral_mesh(const MethodMesh& mesh, const CuttingPlane& blade,
                                                             nlohmann::json& facts, const char* method) {
  return std::make_shared<MeshOf<PolyhedralSceneMesh>>(
      cut_polyhedral_scene_mesh(method_mesh_as<PolyhedralSceneMesh>(mesh, method), blade, facts));
}

}  // namespace altfem
