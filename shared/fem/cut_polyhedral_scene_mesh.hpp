#pragma once
// A polyhedral method's mesh (dg, harmonic) cut by a scene's `cut` event: the polyhedra
// cut (cut_polyhedral_mesh), the surfaces it deforms and loads kept, and the converted
// volume mesh dropped, since its cells no longer match.
#include <memory>
#include <nlohmann/json.hpp>

#include "shared/fem/polyhedral_scene_mesh.hpp"
#include "shared/mesh/cutting_plane.hpp"
#include "shared/simulation/method_mesh.hpp"

namespace altfem {

/// `mesh` cut by `blade`; `facts` gets crossed_cells, separated_faces, duplicated_nodes,
/// snapped_nodes and cells (after). Throws NumericalError as cut_polyhedral_mesh does.
PolyhedralSceneMesh cut_polyhedral_scene_mesh(const PolyhedralSceneMesh& mesh, const CuttingPlane& blade,
                                              nlohmann::json& facts);

/// A polyhedral method's MethodInstance::cut_mesh: its handed mesh (a PolyhedralSceneMesh)
/// cut as above.
std::shared_ptr<const MethodMesh> cut_handed_polyhedral_mesh(const MethodMesh& mesh, const CuttingPlane& blade,
                                                             nlohmann::json& facts, const char* method);

}  // namespace altfem
