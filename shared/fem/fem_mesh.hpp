#pragma once
#include "shared/fem/fem_scene_block.hpp"
#include "shared/mesh/volume_mesh.hpp"
#include "shared/scene/scene_geometry.hpp"

namespace altfem {

/// The conforming mesh the fem method runs on, as discretization.fem asks
/// (docs/scene-schema.md): a structured grid of the geometry's bounding box, CGAL
/// Mesh_3 of the surface or analytic shape (with curved boundary nodes if asked), or
/// the scene's own volume mesh. `fem` is resolved (fem_spec), so every combination
/// it holds works.
VolumeMesh build_fem_mesh(const FemSpec& fem, const SceneGeometry& geometry);

}  // namespace altfem
