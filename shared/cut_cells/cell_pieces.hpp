#pragma once
// Topology-aware finite cells: the connected pieces of the material inside each
// background cell, and which pieces of neighbouring cells the material continues into.
// Longva et al. 2020 (§7, conclusion) name the limitation this removes: a cell holding
// two disconnected parts of the object (a thin slot, two fingers) ties them together
// through its shared DOFs. With one DOF copy per piece (piece_mesh.hpp) they move apart.
#include <array>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "shared/mesh/cell_face_contact.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem {

/// A piece of a neighbouring cell: (background cell, piece index in that cell).
using PieceReference = std::pair<int, int>;

struct CellPieces {
  /// [background cell][piece] → the embedded tetrahedra (ascending indices) whose clip
  /// by the cell has volume; a cell without material has no pieces. Pieces are ordered
  /// by their smallest tetrahedron.
  std::vector<std::vector<std::vector<int>>> tetrahedra;
  /// [background cell][piece] → the pieces of face-neighbouring cells that the material
  /// continues into through the shared face (a contact of positive area), ascending.
  std::vector<std::vector<std::vector<PieceReference>>> neighbours;
  /// [background cell] → 1 where the material fills the cell: its clipped tetrahedra's
  /// volume equals the cell's to filled_cell_tolerance (one piece, and no cut-cell rule
  /// needs to clip them again).
  std::vector<char> filled;

  /// Background cells holding two or more pieces.
  int split_cells() const;
  /// Pieces over all cells.
  int piece_count() const;
};

/// What clipping one embedded tetrahedron by one cell gave (find_cell_pieces), kept for the
/// rebuild an event makes: a cut leaves most tetrahedra as they were, and a pencil's tip
/// cell holds thousands of them, clipped again at every cut before.
struct ClippedTetrahedron {
  bool touches = false;  ///< the clip has volume
  double volume = 0;
  std::array<double, 6> cell_face_area{};
  std::array<double, 4> tetrahedron_face_area{};
};

/// Clips by the hash of the cell's corners and the tetrahedron's (their positions, bit for
/// bit, in order).
using ClippedTetrahedronMemory = std::unordered_map<std::uint64_t, ClippedTetrahedron>;

/// The pieces of every cell of `background` (tetrahedra or hexahedra with planar faces,
/// conforming) over the Tet4 mesh `embedded` of the object (conforming: faces are
/// matched by their corner nodes, so a soup must be welded first (weld_coincident_nodes)
/// and the node copies a cut made on its blade keep the two sides apart).
///
/// Decided combinatorially on the clipped embedded tetrahedra (the brief's second
/// option), not by exact predicates: a fragment is an embedded tetrahedron clipped by a
/// cell (clip_tetrahedron, exact in/out decisions). Within a cell, two fragments are
/// connected when their tetrahedra share a face whose clip by the cell has positive
/// area; across a shared cell face F, a fragment of cell A and one of cell B are
/// connected when both touch F with positive area and they come from the same
/// tetrahedron (it crosses F) or from two tetrahedra sharing a face that lies in F.
/// "Touches with positive area" sums the clipped pieces' triangles whose corners lie
/// within 1e-9 × the cell's diagonal of the plane (the clip rounds new vertices) and
/// asks for a positive sum: the clip's in/out decisions are exact, so a face of the
/// clipped part lies in the plane only where the contact is a surface, however small
/// (a threshold on the area split tiny slivers off spheres). Contacts through an edge
/// or a point only do not connect: the material is continuous only across a surface.
///
/// `contacts` (optional) lists which cells touch across which faces, for a background that
/// is not conforming (a refined grid's: forest_face_contacts); by default faces are matched
/// by their corner nodes.
///
/// `previous` (optional): clips of a build before, taken where the cell and the tetrahedron
/// are the same; `remember` (optional) receives this build's clips.
///
/// Over several ranks every rank calls it alike: each clips every count()-th cell and the
/// fragments are gathered (docs/scaling.md).
CellPieces find_cell_pieces(const VolumeMesh& background, const VolumeMesh& embedded,
                            const std::vector<CellFaceContact>* contacts = nullptr,
                            const ClippedTetrahedronMemory* previous = nullptr,
                            ClippedTetrahedronMemory* remember = nullptr);

}  // namespace altfem
