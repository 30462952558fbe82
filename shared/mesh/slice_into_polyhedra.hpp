#pragma once
// Hexahedral slicing of a closed surface or an analytic shape into a polyhedral mesh
// (Kaufmann et al. 2009, §9.2; Martin et al. 2008, §7): a regular grid over the object's
// bounding box; grid cells wholly inside stay hexahedra, cells the surface crosses become
// the exact intersection of the cell with the object, one polyhedron per connected piece
// (so a thin slot keeps its two sides apart), cells outside are dropped. Interior faces
// are computed once per grid face, so both cells see the same polygon and nodes.
// Pieces below a volume fraction are merged into a neighbour (Kaufmann et al. 2009, §9.4);
// optionally the inside is coarsened by an octree without hanging nodes (octree_grading).
#include "shared/geometry/analytic_shape.hpp"
#include "shared/mesh/polyhedral_mesh.hpp"
#include "shared/mesh/surface_mesh.hpp"

namespace altfem {

struct SlicingOptions {
  int resolution = 16;        ///< cells along the bounding box's longest side (when cell_size is 0)
  double cell_size = 0.0;     ///< edge of the cubic grid cells; > 0 overrides resolution
  double margin_cells = 0.5;  ///< the grid covers the bounding box enlarged by this many cells per side (>= 0)
  /// A cut piece whose volume is below this fraction of a full cell is merged into the
  /// neighbour it shares its largest face with; 0 keeps every piece.
  double sliver_fraction = 1e-3;
  /// Octree grading (Martin et al. 2008, Fig. 4): grid cells wholly inside, away from the
  /// surface, are joined into cells of up to 2^octree_levels grid cells per side; 0 keeps the grid.
  int octree_levels = 0;
};

struct SlicedMesh {
  PolyhedralMesh mesh;
  Eigen::Vector3i grid_cells = Eigen::Vector3i::Zero();
  double cell_size = 0.0;
  int hexahedra = 0;         ///< grid cells wholly inside
  int cut_pieces = 0;        ///< connected pieces of cut grid cells, before merging
  int split_grid_cells = 0;  ///< cut grid cells with more than one piece
  int merged_slivers = 0;    ///< pieces merged into a neighbour
  int coarse_cells = 0;      ///< octree cells of more than one grid cell
  /// Cells by which the grid was moved (beyond margin_cells) because the surface lay in a
  /// grid plane where the two sides' faces could not be told apart; 0 when it was not.
  double grid_shift_cells = 0.0;
};

/// Slices the closed, outward-oriented surface. Where the surface lies in a grid plane in
/// a way the slicer cannot resolve (two bodies closer than a cell, one flush with the
/// plane), the grid moves by a fraction of a cell and the slicing starts again
/// (grid_shift_cells). Throws InputError for bad options and NumericalError naming the
/// grid face where the surface still meets the grid in a way this slicer does not
/// resolve (after three moves, or a surface piercing a grid face without reaching its
/// edges): change the resolution or margin.
SlicedMesh slice_into_polyhedra(const SurfaceMesh& surface, const SlicingOptions& options);

/// Slices an analytic shape (or CSG) through the boundary of its CGAL Mesh_3
/// tetrahedralisation with cells of half the grid's size: the cells' volumes then sum to
/// that triangulated surface's volume, which approximates the shape's.
SlicedMesh slice_into_polyhedra(const AnalyticShape& shape, const SlicingOptions& options);

}  // namespace altfem
