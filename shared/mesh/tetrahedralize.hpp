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
/// shape's level set, with the criteria held below the shape's smallest feature (sizes
/// at most smallest_feature(), facet distance a tenth of the size) and its sharp
/// edges (AnalyticShape::sharp_edges) protected as polyline features, so a cylinder's
/// rims stay sharp; the boundary vertices within 1e-6 of the bounds' diagonal of a planar
/// face (AnalyticShape::planar_faces) are snapped onto it (snap_to_planar_faces). With `bound_cells` false only the
/// surface facets are held to the size (cells are as large as the radius–edge ratio allows): a cheap way to a fine
/// surface of the shape (its boundary_surface).
VolumeMesh tetrahedralize_shape(const AnalyticShape& shape, double max_cell_size, bool bound_cells = true);
/// The exact Tet4 mesh of a shape built from axis-aligned boxes (axis_planes() set):
/// the rectilinear grid through its planes, each interval split into cells of at most
/// 2/√3 · `max_cell_size` (so circumradii stay below it, as with Mesh_3), Kuhn-split,
/// and the cells inside kept. Sharp edges, volume and gaps
/// between boxes are exact, which Mesh_3 does not give.
VolumeMesh tetrahedralize_box_shape(const AnalyticShape& shape, double max_cell_size);

}  // namespace altfem
