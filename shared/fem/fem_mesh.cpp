#include "shared/fem/fem_mesh.hpp"

#include <algorithm>
#include <stdexcept>

#include "shared/mesh/curve_boundary.hpp"
#include "shared/mesh/elevate_order.hpp"
#include "shared/mesh/spatial_order.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "shared/mesh/surface_projection.hpp"
#include "shared/scene/tetrahedralize_geometry.hpp"

namespace altfem {

namespace {

// The grid's cells that `keep` marks, the nodes they use renumbered in their order.
VolumeMesh kept_cells(const VolumeMesh& grid, const std::vector<bool>& keep) {
  std::vector<int> new_index(static_cast<std::size_t>(grid.nodes.rows()), -1);
  Eigen::Index kept = 0;
  for (Eigen::Index cell = 0; cell < grid.cells.rows(); ++cell)
    if (keep[cell]) {
      ++kept;
      for (Eigen::Index k = 0; k < grid.cells.cols(); ++k) new_index[grid.cells(cell, k)] = 0;
    }
  int node_count = 0;
  for (int& index : new_index)
    if (index == 0) index = node_count++;
  VolumeMesh result{grid.element_type, Eigen::MatrixXd(node_count, 3), Eigen::MatrixXi(kept, grid.cells.cols())};
  for (std::size_t node = 0; node < new_index.size(); ++node)
    if (new_index[node] >= 0) result.nodes.row(new_index[node]) = grid.nodes.row(static_cast<Eigen::Index>(node));
  Eigen::Index row = 0;
  for (Eigen::Index cell = 0; cell < grid.cells.rows(); ++cell)
    if (keep[cell]) {
      for (Eigen::Index k = 0; k < grid.cells.cols(); ++k) result.cells(row, k) = new_index[grid.cells(cell, k)];
      ++row;
    }
  return result;
}

}  // namespace

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
      return inside.empty() ? grid : kept_cells(grid, inside);
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
