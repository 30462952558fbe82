#include "shared/fem/fem_mesh.hpp"

#include <algorithm>
#include <stdexcept>

#include "shared/mesh/curve_boundary.hpp"
#include "shared/mesh/elevate_order.hpp"
#include "shared/mesh/spatial_order.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "shared/mesh/surface_projection.hpp"
#include "shared/mesh/volume_mesh_cells.hpp"
#include "shared/scene/tetrahedralize_geometry.hpp"

namespace altfem {

std::vector<bool> grid_cells_in_shape(const FemSpec& fem, const SceneGeometry& geometry) {
  if (!geometry.shape) return {};
  const Eigen::Vector3d size = geometry.bounds.sizes().cwiseQuotient(fem.resolution.cast<double>());
  std::vector<bool> inside;
  inside.reserve(static_cast<std::size_t>(fem.resolution.prod()));
  for (int k = 0; k < fem.resolution.z(); ++k)
    for (int j = 0; j < fem.resolution.y(); ++j)
      for (int i = 0; i < fem.resolution.x(); ++i)
        inside.push_back(geometry.shape->contains(
            geometry.bounds.min() + (Eigen::Vector3d(i, j, k).array() + 0.5).matrix().cwiseProduct(size)));
  if (std::all_of(inside.begin(), inside.end(), [](bool in) { return in; })) return {};
  return inside;
}

VolumeMesh build_fem_mesh(const FemSpec& fem, const SceneGeometry& geometry) {
  switch (fem.mesh) {
    case FemMeshKind::grid: {
      VolumeMesh grid = structured_grid(geometry.bounds, fem.resolution, fem.element);
      const std::vector<bool> inside = grid_cells_in_shape(fem, geometry);
      if (inside.empty()) return grid;
      std::vector<int> kept;
      for (std::size_t cell = 0; cell < inside.size(); ++cell)
        if (inside[cell]) kept.push_back(static_cast<int>(cell));
      return volume_mesh_cells(grid, kept);
    }
    case FemMeshKind::tetrahedralize: {
      // fem_scene_block has checked that fem.element is a tetrahedron.
      const double size = fem_max_cell_size(fem, geometry.bounds);
      VolumeMesh linear = tetrahedralize_geometry(geometry, size, fem.pointer + "/max_cell_size");
      VolumeMesh mesh = elevate_order(linear, fem.element);
      if (fem.curved && fem.element != ElementType::tet4) {
        if (geometry.surface) {
          const SurfaceProjection projection(*geometry.surface);
          curve_boundary(mesh, [&](const Eigen::Vector3d& x) { return projection.closest_point(x); });
        } else {
          const double step = 1e-7 * geometry.bounds.diagonal().norm();
          const auto level_set = [&](const Eigen::Vector3d& x) { return geometry.shape->level_set(x); };
          curve_boundary(mesh, [&](const Eigen::Vector3d& x) { return project_to_level_set(level_set, x, step); });
        }
      }
      // Mesh_3's cell and vertex order is nearly random in space (spatial_order.hpp).
      return spatially_ordered(mesh);
    }
    case FemMeshKind::file:
      // fem_scene_block has checked that the file's cells are fem.element.
      return *geometry.mesh;
  }
  throw std::logic_error("build_fem_mesh: unknown mesh kind");
}

}  // namespace altfem
