#include "shared/fem/polyhedral_scene_mesh.hpp"

#include "shared/fem/fem_mesh.hpp"
#include "shared/mesh/boundary_surface.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"
#include "shared/scene/scene_slicing.hpp"

namespace altfem {

PolyhedralSceneMesh build_polyhedral_scene_mesh(const PolyhedralMeshSource& source, const SceneGeometry& geometry) {
  PolyhedralSceneMesh result;
  if (source.slicing) {
    result.sliced = slice_scene_geometry(geometry, *source.slicing);
    result.surface = sliced_surface(geometry);
    result.facts = {{"source", "slice"}, {"slicing", slicing_facts(result.sliced)}};
    return result;
  }
  const VolumeMesh volume = build_fem_mesh(source.convert, geometry);
  result.sliced.mesh = polyhedral_mesh_from_volume_mesh(volume);
  result.surface = geometry.common_surface() ? *geometry.common_surface() : boundary_surface(volume).surface;
  result.facts = {{"source", "convert"}};
  return result;
}

}  // namespace altfem
