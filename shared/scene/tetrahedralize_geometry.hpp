#pragma once
// The Tet4 mesh of a scene geometry's inside, checked against the geometry: every
// method that tetrahedralises a surface or an analytic shape goes through here, so no
// method glues together what the geometry keeps apart (docs/meshes.md, "Checks").
#include <string>

#include "shared/mesh/volume_mesh.hpp"
#include "shared/scene/scene_geometry.hpp"

namespace altfem {

/// Shapes built from axis-aligned boxes are meshed exactly (tetrahedralize_box_shape),
/// other shapes by Mesh_3 with their sharp edges protected, surfaces by Mesh_3. Then
/// checked: the mesh has as many face-connected pieces as a surface has solid shells,
/// or at least as many as a shape has on a voxel grid of a quarter of the cell size
/// (parts closer than that are not told apart, so more pieces is no error); no cell
/// centroid lies outside the geometry by more than the facet distance (a tenth of the
/// cell size); the volume is within 20% (a gross check: Mesh_3 at a coarse size loses
/// several percent of a curved shape by design).
/// A failed check throws InputError naming the scene file and `size_key` (the JSON
/// pointer of the cell-size setting, e.g. /discretization/fem/max_cell_size) with what
/// to change.
VolumeMesh tetrahedralize_geometry(const SceneGeometry& geometry, double max_cell_size, const std::string& size_key);

/// The relative volume tolerance of the check.
inline constexpr double tetrahedralization_volume_tolerance = 0.2;

}  // namespace altfem
