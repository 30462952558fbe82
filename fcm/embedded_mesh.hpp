#pragma once
// The tetrahedral mesh of the embedded object that intersection quadrature clips
// (Longva et al. 2020, §4.5): a scene's tetrahedral volume mesh as it is, or its
// surface or analytic shape tetrahedralised and checked by tetrahedralize_geometry.
#include "shared/mesh/volume_mesh.hpp"
#include "shared/scene/scene_geometry.hpp"

namespace altfem::fcm {

/// A Tet4 mesh of the geometry, welded (weld_coincident_nodes): a Tet4/Tet10 volume mesh's corner tetrahedra; a
/// hexahedral volume mesh's cells split into 12 tetrahedra each about their centroids
/// (tetrahedra_of_hexahedra: straight-sided, so a Hex20/Hex27 cell's curved faces and a
/// Hex8 cell's warped ones are approximated by triangles); a surface or shape meshed with
/// cells of at most `max_cell_size`.
VolumeMesh embedded_tetrahedra(const SceneGeometry& geometry, double max_cell_size, const std::string& scene_file);

}  // namespace altfem::fcm
