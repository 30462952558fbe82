#pragma once
// Merging cells of a polyhedral mesh: sliver merging (Kaufmann et al. 2009, §9.4) — a cut
// piece much smaller than a grid cell makes the methods' element matrices ill-conditioned,
// so it joins the neighbour it shares its largest face with; the union may be non-convex —
// and the groups of octree grading.
#include <vector>

#include "shared/mesh/disjoint_sets.hpp"
#include "shared/mesh/polyhedral_mesh.hpp"

namespace altfem {

/// Merges every `cut` cell whose volume is below `minimum_volume` (smallest first) into
/// the face-neighbour across its largest interior face; faces between merged cells are
/// removed, unused nodes dropped, the merged cells' kind becomes `merged`, and the
/// geometry is recomputed. A piece without neighbours (a separate bit of the object) is
/// kept. Returns the number of cells merged away. Needs the geometry computed.
int merge_slivers(PolyhedralMesh& mesh, double minimum_volume);

/// What merge_small_pieces did: the cells merged away, and per node of the result its
/// index before (nodes keep their order).
struct MergedPieces {
  int merged = 0;
  std::vector<int> kept_nodes;
  std::vector<int> new_cell;  ///< per cell before, the cell it became part of (empty when none merged)
};

/// merge_slivers with a threshold per cell (#cells of `mesh`; 0 keeps a cell whatever its
/// volume): a cell whose volume is below its threshold joins the face-neighbour across its largest interior face.
MergedPieces merge_small_pieces(PolyhedralMesh& mesh, const std::vector<double>& minimum_volume);

/// The mesh with each group of cells (the sets of `groups`, over the cell indices) as one
/// cell of kind `grouped_kind` (a cell alone keeps its kind): faces inside a group are
/// dropped and nodes no face uses are removed. The geometry arrays are left stale: call
/// compute_polyhedral_geometry.
/// Returns, per node of the result, its index before; `new_cell` (optional) receives, per
/// cell before, the cell of the result it is part of.
std::vector<int> merge_cell_groups(PolyhedralMesh& mesh, DisjointSets& groups, PolyhedralCellKind grouped_kind,
                                   std::vector<int>* new_cell = nullptr);

/// Removes the nodes no face uses, renumbering the faces' loops; the others keep their
/// order. Returns, per node of the result, its index before.
std::vector<int> drop_unused_nodes(PolyhedralMesh& mesh);

}  // namespace altfem
