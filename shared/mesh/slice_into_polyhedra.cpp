#include "shared/mesh/slice_into_polyhedra.hpp"

#include <array>
#include <cmath>

#include "shared/common/error.hpp"
#include "shared/mesh/boundary_surface.hpp"
#include "shared/mesh/grid_slicer.hpp"
#include "shared/mesh/merge_slivers.hpp"
#include "shared/mesh/octree_grading.hpp"
#include "shared/mesh/tetrahedralize.hpp"

namespace altfem {

namespace {

void check_options(const SlicingOptions& options) {
  if (options.cell_size < 0 || (options.cell_size == 0 && options.resolution < 1))
    throw InputError("slicing: resolution must be >= 1 or cell_size > 0");
  if (!(options.margin_cells >= 0)) throw InputError("slicing: margin must be >= 0 cells");
  if (!(options.sliver_fraction >= 0 && options.sliver_fraction < 1))
    throw InputError("slicing: sliver fraction must be in [0, 1)");
  if (options.octree_levels < 0 || options.octree_levels > 10)
    throw InputError("slicing: octree levels must be in 0..10");
}

double cell_size_for(const SlicingOptions& options, const Eigen::Vector3d& lower, const Eigen::Vector3d& upper) {
  return options.cell_size > 0 ? options.cell_size : (upper - lower).maxCoeff() / options.resolution;
}

// Octree grading, the geometry, sliver merging and unused nodes after a successful pass.
SlicedMesh finish(SlicedMesh result, const SlicingGrid& grid, const GridSlicer& slicer, const SlicingOptions& options) {
  if (options.octree_levels > 0)
    result.coarse_cells =
        grade_interior_hexahedra(result.mesh, grid.cells, slicer.grid_hexahedra(), options.octree_levels);
  compute_polyhedral_geometry(result.mesh);
  if (options.sliver_fraction > 0)
    result.merged_slivers = merge_slivers(result.mesh, options.sliver_fraction * std::pow(grid.cell_size, 3));
  // Surface vertices inside a planar part of the boundary (a triangle fan's centre) are
  // no corner of the merged face polygon: a conforming method would give them degrees of
  // freedom with no support (zero mass and stiffness).
  drop_unused_nodes(result.mesh);
  return result;
}

}  // namespace

SlicedMesh slice_into_polyhedra(const SurfaceMesh& surface, const SlicingOptions& options) {
  check_options(options);
  if (surface.triangles.rows() == 0) throw InputError("slicing: the surface has no triangles");
  const Eigen::Vector3d lower = surface.vertices.colwise().minCoeff(), upper = surface.vertices.colwise().maxCoeff();
  const double cell_size = cell_size_for(options, lower, upper);
  // A face of the surface in a grid plane with the slicer unable to tell the sides'
  // faces apart (two bodies closer than a cell, one of them flush with a plane): move the
  // grid by a fraction of a cell that no common coordinate shares (golden-ratio steps)
  // and slice again, rather than ask the user for another resolution.
  constexpr std::array<double, 4> shifts{0.0, 0.381966011, 0.236067977, 0.145898034};
  for (std::size_t attempt = 0;; ++attempt) {
    const SlicingGrid grid = SlicingGrid::covering(lower, upper, cell_size, options.margin_cells + shifts[attempt]);
    GridSlicer slicer(surface, grid);
    try {
      SlicedMesh result = slicer.run();
      result.grid_shift_cells = shifts[attempt];
      return finish(std::move(result), grid, slicer, options);
    } catch (const SurfaceInGridPlane&) {
      if (attempt + 1 == shifts.size()) throw;
    }
  }
}

SlicedMesh slice_into_polyhedra(const AnalyticShape& shape, const SlicingOptions& options) {
  check_options(options);
  const Eigen::AlignedBox3d box = shape.bounding_box();
  const double cell_size = cell_size_for(options, box.min(), box.max());
  const SurfaceMesh surface = boundary_surface(tetrahedralize_shape(shape, cell_size / 2)).surface;
  SlicingOptions surface_options = options;
  surface_options.cell_size = cell_size;
  return slice_into_polyhedra(surface, surface_options);
}

}  // namespace altfem
