#pragma once
// A mesh of arbitrary polyhedra (convex or not, planar polygonal faces) with face
// adjacency: the common ground of the DG (Kaufmann et al. 2009, §9) and harmonic
// (Martin et al. 2008, §7) methods. Every face is stored once; an interior face is the
// SAME polygon seen from both of its cells, so DG face couplings and conforming
// (node-sharing) harmonic bases both read it directly.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "shared/geometry/polyhedron.hpp"

namespace altfem {

/// Where a cell came from (written to VTU as the integer cell data "kind").
enum class PolyhedralCellKind : int {
  tetrahedron = 0,  ///< a tetrahedron of a converted volume mesh
  hexahedron = 1,   ///< a hexahedron of a converted volume mesh, or a grid cell wholly inside a sliced object
  cut = 2,     ///< one connected piece of a grid cell cut by a sliced object's surface, or of a non-convex cell a blade
               ///< crossed
  merged = 3,  ///< a cell with sliver pieces merged into it (merge_slivers)
  coarse = 4,  ///< an octree cell: 2^(3L) grid cells wholly inside, its finer neighbours' nodes on its faces
  refined = 5,  ///< a convex piece of a cell split by refinement (split_polyhedral_cells)
  split = 6,    ///< a convex piece of a convex cell a blade's plane crossed (cut_polyhedral_mesh)
};

/// Cells of this kind are convex: a point in front of one of their face planes is outside.
inline bool convex_kind(PolyhedralCellKind kind) {
  return kind == PolyhedralCellKind::tetrahedron || kind == PolyhedralCellKind::hexahedron ||
         kind == PolyhedralCellKind::refined || kind == PolyhedralCellKind::split;
}

struct PolyhedralMesh {
  Eigen::MatrixXd nodes;  ///< #nodes × 3
  /// Each face: a loop of node indices (>= 3) of a planar simple polygon, counter-clockwise
  /// seen from outside face_cells(f, 0), i.e. its right-hand normal points out of that cell.
  std::vector<std::vector<int>> faces;
  /// #faces × 2: the cell the face loop is oriented for, and the cell on its other side,
  /// or -1 for a boundary face.
  Eigen::MatrixXi face_cells;
  /// Per cell, the indices into `faces` of its boundary (closed surface).
  std::vector<std::vector<int>> cell_faces;
  std::vector<PolyhedralCellKind> cell_kinds;  ///< #cells

  // Geometry, filled by compute_polyhedral_geometry.
  Eigen::VectorXd cell_volumes;    ///< #cells
  Eigen::MatrixXd cell_centroids;  ///< #cells × 3
  Eigen::VectorXd cell_diameters;  ///< #cells: largest distance between two of the cell's nodes
  Eigen::VectorXd face_areas;      ///< #faces
  Eigen::MatrixXd face_normals;    ///< #faces × 3, unit, out of face_cells(f, 0)
  Eigen::MatrixXd face_centroids;  ///< #faces × 3

  int cell_count() const { return static_cast<int>(cell_faces.size()); }
  int face_count() const { return static_cast<int>(faces.size()); }
  bool is_boundary_face(int face) const { return face_cells(face, 1) < 0; }
};

/// Cell `cell` as a standalone Polyhedron (its own vertex numbering, every face
/// counter-clockwise seen from outside that cell): what polyhedron_moments integrates.
Polyhedron cell_polyhedron(const PolyhedralMesh& mesh, int cell);

/// Fills the geometry arrays from nodes, faces and face_cells by the exact moments
/// (polyhedron_moments, planar_polygon_moments). Throws std::invalid_argument for a face
/// with < 3 nodes, a node index out of range or face_cells not #faces × 2, and
/// NumericalError naming the cell when a cell's volume is not positive.
void compute_polyhedral_geometry(PolyhedralMesh& mesh);

/// Newell's area vector of the polygon of `loop`'s nodes, summed about its first node: its
/// area times its unit normal. About the origin the sum rounds to 1e-17, which hides a
/// face a few ulps across.
Eigen::Vector3d face_area_vector(const PolyhedralMesh& mesh, const std::vector<int>& loop);

/// Sets the mesh's faces to `loops` (each oriented for the first cell of its `cells` entry,
/// the second −1 on the boundary) and rebuilds `face_cells` and `cell_faces` (cells keep their
/// count). Geometry left stale.
void set_faces(PolyhedralMesh& mesh, std::vector<std::vector<int>> loops, const std::vector<std::array<int, 2>>& cells);

/// The mesh without the cells `keep` drops (their faces with a kept cell become that
/// cell's boundary faces); nodes keep their numbers, geometry arrays are left empty.
/// `kept` receives each kept cell's index; `kept_faces`, when given, each kept face's.
PolyhedralMesh polyhedral_mesh_with_cells(const PolyhedralMesh& mesh, const std::vector<bool>& keep,
                                          std::vector<int>& kept, std::vector<int>* kept_faces = nullptr);

}  // namespace altfem
