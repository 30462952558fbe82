#pragma once
#include "shared/geometry/analytic_shape.hpp"
#include "shared/mesh/surface_mesh.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem {

/// A Tet4 mesh of the inside of a closed surface by CGAL Mesh_3 (Delaunay
/// refinement with sizing `max_cell_size` for cells and surface facets, facet
/// distance max_cell_size / 10, radius–edge ratio 3; no perturbation or exudation so
/// the result is repeatable with Mesh_3's seeded random generator).
/// Mesh_3 only approximates the input surface: some surface vertices fall outside.
VolumeMesh tetrahedralize_surface(const SurfaceMesh& surface, double max_cell_size);
/// The same for an analytic shape, through Mesh_3's implicit-function domain on the
/// shape's level set.
VolumeMesh tetrahedralize_shape(const AnalyticShape& shape, double max_cell_size);

}  // namespace altfem
