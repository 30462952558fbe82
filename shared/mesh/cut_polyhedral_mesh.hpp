#pragma once
// A polyhedral mesh cut by a planar blade (Kaufmann et al. 2009 §9.4, Martin et al. 2008
// §8): every cell the plane crosses becomes its two pieces, and what the blade separates
// separates — the pieces' faces on the blade, and mesh faces that lie in it, are boundary
// faces, and the nodes on them are duplicated, one copy per group of pieces they hold
// that no longer meet through a face. A finite blade (a convex polygon) separates only
// the sections it covers whole: a cell its edge runs through is split into two pieces
// that stay joined (the face between them interior), as is every cell the plane crosses
// that meets those through faces the plane crosses, so the mesh stays conforming. A blade
// with `piece_at` cuts only the piece of the mesh (connected through faces) holding the
// node nearest that point. Every side
// decision is an exact orientation predicate on the nodes as stored, so a blade through
// nodes, along edges or in faces is an ordinary case; a node a few hundred ulps off the
// blade is taken on it, so that no piece is thinner than that.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <vector>

#include "shared/mesh/cutting_plane.hpp"
#include "shared/mesh/polyhedral_mesh.hpp"

namespace altfem {

/// Where a node of a cut mesh comes from: (1 − weight) × input node `first` + weight ×
/// input node `second` — an input node (itself, weight 0), the copy of one on the blade,
/// or a crossing node on the edge (first, second). A nodal field carried through this is
/// exact wherever the basis is linear along edges, and never confuses the copies of a
/// node that an earlier cut duplicated (they share a position).
struct NodeSource {
  int first = 0, second = 0;
  double weight = 0;
};

struct PolyhedralCut {
  PolyhedralMesh mesh;                   ///< the cut mesh, its geometry computed unless asked not to
  std::vector<int> parent_cell;          ///< #cells of `mesh`: the cell of the input it lies in
  std::vector<NodeSource> node_sources;  ///< #nodes of `mesh`
  int crossed_cells = 0;                 ///< input cells split into pieces (two, or a non-convex cell's parts)
  int joined_cells = 0;                  ///< of those, the ones whose pieces stay joined (finite blades)
  int separated_faces = 0;               ///< interior input faces in the plane, now two boundary faces
  int duplicated_nodes = 0;              ///< copies of nodes on the opened faces
  int snapped_nodes = 0;                 ///< nodes off the plane by less than 1e-13 of the mesh's diagonal, taken on it
  int merged_pieces = 0;                 ///< pieces without a positive rounded volume, merged into a neighbour
  int merged_faces =
      0;  ///< surface blades: faces in one plane between the same cells, made one (simplify_cut_faces.hpp)
  int dropped_nodes = 0;   ///< surface blades: nodes in the middle of a straight edge, removed
  int dropped_pieces = 0;  ///< surface blades: slivers of rounding volume cut off whole, dropped (cut_by_surface.hpp)
};

/// What a cut does. A surface blade (cut_by_surface.hpp) is the steps `split` and `separate`
/// per triangle, so that what it separates is exactly its triangles.
enum class CutAction {
  cut,       ///< split the cells the plane crosses, separate what the blade covers (above)
  split,     ///< split the crossed cells in `region` into pieces that stay joined; separate nothing
  separate,  ///< split nothing; separate the interior faces in the plane whose centroid the blade covers
};

struct CutScope {
  CutAction action = CutAction::cut;
  /// split: only the cells whose bounding box meets this box (unset: every cell). A face of
  /// a cell left whole gets the crossing nodes of its edges (kind split), so the mesh stays
  /// conforming. separate: where the blade is (a caller skips a step whose box misses the mesh).
  std::optional<Eigen::AlignedBox3d> region;
  /// split: also every cell joined to one in `region` through faces the plane crosses, so
  /// that no cell left whole has a face split (a convex fragment's tetrahedra need that:
  /// cut_tetrahedral_mesh).
  bool spread = false;
  /// When set, nodes taken on the plane besides those on it or within the snapping
  /// distance (a surface blade's step knows which nodes an earlier step made on its
  /// triangle's plane, a rounding off it).
  const std::vector<int>* on_plane = nullptr;
  /// The snapping distance (above) as a fraction of the mesh's bounding-box diagonal. A
  /// surface blade's steps take 1e-9 (cut_by_surface.cpp says why); a split step that it
  /// leaves with a face it cannot split (nodes of a tiny face where several of its
  /// triangles meet, some snapped, some not) is made again with 1e-15: a few ulps, so that
  /// no crossing node rounds onto an end of its edge.
  double snap_fraction = 1e-13;
  /// The length `snap_fraction` is a fraction of; 0: the mesh's bounding-box diagonal. A
  /// surface blade cuts a window of the mesh at a time (polyhedral_mesh_window.hpp) and
  /// snaps as the whole mesh would.
  double snap_length = 0;
};

/// Cuts `mesh` by `plane`. A crossed convex cell becomes two convex pieces (kind split);
/// a crossed non-convex one becomes the connected parts of each side (kind cut): a face
/// falls into as many polygons as the plane leaves of it, a section into as many caps.
/// Two parts of a side that meet only along an edge in the plane stay one piece. A section
/// with holes (a cell that is a ring around the blade's path) becomes caps that are simple
/// polygons, each hole bridged to its outer loop (split_holes). Throws NumericalError naming
/// the cell when a section does not close or its holes cannot be bridged. Throws std::invalid_argument for a zero
/// normal or a blade polygon with a blade_polygon_problem. A plane that misses every cell returns the mesh unchanged.
/// Without `compute_geometry` the cut mesh's geometry arrays stay empty, and a piece too thin for its rounded volume to
/// be positive is the caller's to handle (cut_tetrahedral_mesh); with it, such a piece is merged into the cell across
/// its largest interior face (merge_pieces_without_volume; NumericalError when it has none).
/// A blade with a `surface` is cut_polyhedral_mesh_by_surface's (`scope` is for planes only).
PolyhedralCut cut_polyhedral_mesh(const PolyhedralMesh& mesh, const CuttingPlane& plane, bool compute_geometry = true,
                                  const CutScope& scope = {});

}  // namespace altfem
