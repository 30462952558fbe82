#pragma once
// The cells an event left alone, found again in the build before, so that their stiffness
// points are copied, not evaluated again (Martin et al. 2008 §8: only cut elements get new
// bases; the rest keep theirs, and so their tabulation). The event's mesh may list a kept
// cell otherwise (other node numbers, faces in another order, loops from another node):
// it is matched in its canonical listing (canonical_cell): its vertices' positions, exactly,
// and its faces' loops through them.
#include <vector>

#include "polyhedral/element_harmonic_basis.hpp"
#include "shared/mesh/polyhedral_mesh.hpp"

namespace altfem::harmonic {

/// Where a cell's tabulation can come from: the earlier build's cell and, per local node
/// of this cell (cell_nodes order), that cell's local node at the same position.
struct EarlierCell {
  int cell = -1;  ///< −1: none
  std::vector<int> order;
};

/// Per cell of `mesh`, the cell of `earlier_mesh` that is the same polyhedron (the same
/// vertex positions, bit for bit, pairwise distinct, and the same oriented face loops
/// through them) with the same basis up to that node order (`bases[cell]` equals
/// `earlier_bases[match].reordered(order)` bit for bit, by content key). A cell whose
/// basis pointer is null, or whose `candidate` entry is false, or an earlier cell whose
/// `earlier_candidate` entry is false, takes part in no match.
std::vector<EarlierCell> match_earlier_cells(const PolyhedralMesh& mesh,
                                             const std::vector<const ElementHarmonicBasis*>& bases,
                                             const std::vector<char>& candidate, const PolyhedralMesh& earlier_mesh,
                                             const std::vector<const ElementHarmonicBasis*>& earlier_bases,
                                             const std::vector<char>& earlier_candidate);

}  // namespace altfem::harmonic
