#pragma once
// A mesh cell as an MFS fit sees it, whatever the mesh's numbering and however it lists
// the cell's faces: its vertices sorted by position, each face loop (outward) from its
// lowest vertex, the loops sorted. The fit samples its faces in order from frames their
// loops set and keeps the first of close kernel centres (element_harmonic_basis.cpp), so a
// fit on the cell as listed depends on the listing: two listings of one cell agree only to
// the fit's accuracy (1e-4 on a box). On the canonical cell, cells alike but for their
// place and size (a refinement's cells, on every level; the pieces a blade cuts across a
// grid) get the same samples, moved and scaled, and fits that agree to round-off.
#include <vector>

#include "shared/geometry/polyhedron.hpp"
#include "shared/mesh/polyhedral_mesh.hpp"

namespace altfem::harmonic {

struct CanonicalCell {
  Polyhedron polyhedron;        ///< vertices (#vertices × 3) sorted; faces outward, canonical
  std::vector<int> nodes;       ///< the cell's mesh nodes in cell_polyhedron order (cell_nodes)
  std::vector<int> local;       ///< per sorted vertex, its index in that order
  std::vector<int> sorted;      ///< per cell_polyhedron vertex, its sorted index
  std::vector<int> mesh_faces;  ///< per canonical face, the mesh face it is
};

CanonicalCell canonical_cell(const PolyhedralMesh& mesh, int cell);

}  // namespace altfem::harmonic
