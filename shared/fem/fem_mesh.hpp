#pragma once
#include "shared/fem/fem_scene_block.hpp"
#include "shared/mesh/volume_mesh.hpp"
#include "shared/scene/scene_geometry.hpp"

namespace altfem {

/// The conforming mesh the fem method runs on, as discretization.fem asks
/// (docs/scene-schema.md): a structured grid of the geometry's bounding box (of a shape
/// built of boxes, its cells inside the shape: grid_cells_in_shape), CGAL
/// Mesh_3 of the surface or analytic shape (with curved boundary nodes if asked), or
/// the scene's own volume mesh. `fem` is resolved (fem_spec), so every combination
/// it holds works.
VolumeMesh build_fem_mesh(const FemSpec& fem, const SceneGeometry& geometry);

/// Per cell of the structured grid of `fem.resolution` over the geometry's bounds (x
/// fastest), whether it lies in the shape: its centre does. fem_scene_block has checked
/// that the shape is built of boxes whose faces lie on the grid's planes, so every cell is
/// wholly in or out. Empty when every cell is in (a box).
std::vector<bool> grid_cells_in_shape(const FemSpec& fem, const SceneGeometry& geometry);

}  // namespace altfem
