#pragma once
// Cells of a polyhedral mesh split by planes through them, the mesh kept conforming: the
// refinement of Kaufmann et al. 2009 §9.3 (1→8 by three planes through the centroid, 1→2
// by the plane normal to the principal stress direction) and Martin et al. 2008 §8. Unlike
// a cut nothing separates: the faces between a cell's children are interior faces, a
// neighbour's face is split where the child faces on it are, and a node a split puts on an
// edge becomes a node of every face holding that edge — a hanging node is just a vertex of
// the unsplit neighbour (Martin et al. 2008 §8), and no neighbour is split to balance.
// Every side decision is CGAL's exact orientation of exactly constructed points (each new
// node is the exact crossing of a split plane with an edge or chord, rounded only when
// stored), so a plane through nodes, along edges or in faces is an ordinary case; a node
// within 10⁻¹² of the mesh's diagonal of a plane is taken on it, so that the nearly equal
// planes of neighbours make one node where they cross an edge, not two a few ulps apart.
#include <Eigen/Core>
#include <vector>

#include "shared/mesh/polyhedral_mesh.hpp"

namespace altfem {

/// The points x with normal · x = offset (the doubles as given define the plane exactly).
struct SplitPlane {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();
  double offset = 0;
};

/// The plane through `point` with this normal: offset = normal · point, rounded, so that
/// cells whose centres share a coordinate share the axis plane through it bit for bit.
inline SplitPlane plane_through(const Eigen::Vector3d& point, const Eigen::Vector3d& normal) {
  return {normal, normal.dot(point)};
}

struct CellSplit {
  int cell = 0;
  std::vector<SplitPlane> planes;  ///< 1 to 3: the cell becomes the (up to 2^#planes) pieces between them
};

struct SplitCells {
  /// The split mesh, its geometry computed. The input's nodes come first, in order, the new
  /// ones after them. An unsplit cell keeps its index; a split cell's first piece takes the
  /// cell's index and its other pieces follow the input's cells.
  PolyhedralMesh mesh;
  std::vector<int> parent_cell;  ///< #cells of `mesh`: the input cell each lies in
  int split_cells = 0;           ///< input cells split
  int new_nodes = 0;             ///< nodes added (on edges, in faces, inside cells)
  int hanging_nodes = 0;         ///< of those, the ones on a face of a cell that was not split
};

/// Splits every listed cell by its planes. A split cell must be convex (is_convex_cell) and
/// listed once; throws std::invalid_argument otherwise, or for a cell out of range, no
/// planes, more than 3 or a zero normal. Throws NumericalError naming the cell when a face
/// lies in one of the cell's own planes or a piece's volume is not positive.
SplitCells split_polyhedral_cells(const PolyhedralMesh& mesh, const std::vector<CellSplit>& splits);

}  // namespace altfem
