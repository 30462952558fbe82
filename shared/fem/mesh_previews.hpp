#pragma once
// `altfem mesh` for the methods on Lagrange and polyhedral meshes (fem, dg, harmonic):
// the mesh built as `run` builds it, its facts, and the lines the command prints.
#include <nlohmann/json.hpp>
#include <string>

#include "shared/fem/polyhedral_scene_mesh.hpp"
#include "shared/mesh/polyhedral_mesh.hpp"
#include "shared/scene/scene.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/simulation/mesh_preview.hpp"

namespace altfem {

/// Cells by kind, faces, nodes, the mesh's volume against the geometry's, and the range
/// of cell volumes.
nlohmann::json polyhedral_mesh_facts(const PolyhedralMesh& mesh, double geometry_volume);

/// dg's and harmonic's mesh: the one their block names (`block_source`), or with the
/// options' source the fem mesh converted cell by cell (`convert`) or the geometry sliced
/// by the options' grid (`slice`). Throws InputError for another source.
MeshPreview polyhedral_mesh_preview(const std::string& method, const Scene& scene, const SceneGeometry& geometry,
                                    PolyhedralMeshSource block_source, const MeshPreviewOptions& options);

/// fem's mesh; its facts from the same conversion (straight-sided cells from the corners,
/// the node count the written mesh's, higher-order nodes included). No source option.
MeshPreview fem_mesh_preview(const Scene& scene, const SceneGeometry& geometry, const MeshPreviewOptions& options);

}  // namespace altfem
