#pragma once
// The last two steps of cutting a polyhedral mesh (cut_polyhedral_mesh): the parts a
// non-convex cell's side falls into become pieces of their own, and the nodes the cut
// opened are copied for each group of pieces that no longer meet around them.
#include <Eigen/Core>
#include <vector>

#include "shared/mesh/cut_polyhedral_mesh.hpp"

namespace altfem {

/// A face of the cut mesh before node duplication: its loop, the pieces on its two sides
/// (second −1 on the boundary), the side of the blade it lies on, and whether the cut
/// opened it (a boundary face that was inside the body).
struct CutFace {
  std::vector<int> loop;
  int first = -1, second = -1, sigma = +1;
  bool opened = false;
};

struct CutPieces {
  std::vector<int> parent;  ///< per piece, its input cell
  std::vector<int> sigma;   ///< per piece, the side of the blade it lies on (±1)
};

/// Each half (a cell's side of the blade; `half_parent`, `half_sigma` per half) whose
/// `separates` is set becomes one piece per connected part of its faces (faces sharing an
/// edge are connected), numbered in the order of its faces; the others stay one piece.
/// Renumbers `faces`' first and second from halves to pieces.
CutPieces separate_disconnected_parts(std::vector<CutFace>& faces, const std::vector<int>& half_parent,
                                      const std::vector<int>& half_sigma, const std::vector<bool>& separates);

/// A node with `opened_node` set is held by pieces that may now lie apart: those joined
/// through the faces holding it that are not boundary faces form a group, and each group
/// but one gets a copy of the node (appended to `nodes` and `sources`) — the group kept is
/// the first with a piece on the positive side (`piece_sigma`), so a cut by the whole plane
/// copies each node once, for the negative side. At a finite blade's edge the pieces stay
/// joined around the node: it is not copied. Returns the number of copies.
int duplicate_separated_nodes(std::vector<CutFace>& faces, const std::vector<bool>& opened_node,
                              const std::vector<int>& piece_sigma, std::vector<Eigen::Vector3d>& nodes,
                              std::vector<NodeSource>& sources);

/// Joins each piece with `is_piece` set whose rounded volume is not positive to the cell
/// across its largest interior face (kind merged): a blade a few 1e-12 from nodes leaves
/// pieces thinner than round-off, whose faces' rounding decides their volume's sign (Kaufmann
/// et al. 2009 §9.4 merge negligible pieces). Such a piece without an interior face is left.
/// Renumbers `parent` (per cell) and `sources` (per node) with the merged mesh, whose
/// geometry is left stale. Returns the number of pieces merged away.
int merge_pieces_without_volume(PolyhedralMesh& mesh, std::vector<int>& parent, std::vector<NodeSource>& sources,
                                const std::vector<bool>& is_piece);

}  // namespace altfem
