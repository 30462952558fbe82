#pragma once
// The pieces a surface blade's steps leave (cut_by_surface.hpp) joined again: after each
// flat part of the blade, a cell's pieces a side of its plane, so that fcm's and fem's
// fragments stay convex; after the whole blade, a cell's pieces the blade did not part,
// for dg's and harmonic's cells, which may be non-convex. Neither joins two pieces across
// a slit, where the blade opened the face between them.
#include <vector>

#include "shared/mesh/cutting_plane.hpp"
#include "shared/mesh/polyhedral_mesh.hpp"

namespace altfem {

/// Joins again the pieces of each cell that a blade did not part (`parent_cell`: per cell
/// of `mesh`, the cell it is a piece of; updated): pieces of one parent next to one another
/// through an interior face become one cell (kind cut; faces between them dropped), face
/// by face, but never two that hold the two sides of a slit (boundary faces at the same
/// positions: where the blade ends inside the cell, its pieces meet around the blade's
/// edge, and one cell could not open there). Geometry left stale. Returns the number of
/// pieces joined away.
int join_unparted_pieces(PolyhedralMesh& mesh, std::vector<int>& parent_cell);

/// After the steps of one flat part of a blade (`plane` its own): joins again the pieces of
/// each cell (per `parent_cell`, updated) on each side of `plane`, and the two sides too
/// where its separations opened no face between them. Each cell so made is its parent's
/// part on one side of the plane, or the parent, so a convex parent stays convex: the
/// edges' splits only bounded the faces the separations could open, and a cell the steps
/// reached but did not part leaves them no pieces. Geometry left stale. `kept_nodes`
/// (optional): per node of the result, its index before (the nodes inside a joined cell
/// dropped). Returns the number of pieces joined away.
int join_pieces_by_side(PolyhedralMesh& mesh, std::vector<int>& parent_cell, const CuttingPlane& plane,
                        std::vector<int>* kept_nodes = nullptr);

}  // namespace altfem
