#pragma once
// Whether a cell of a polyhedral mesh is convex: what cut_polyhedral_mesh's two-piece
// construction of a crossed cell needs.
#include <vector>

#include "shared/mesh/polyhedral_mesh.hpp"

namespace altfem {

/// Each of `cell_nodes` (the nodes of `cell`) on or behind the plane of each face of
/// `cell` (the plane of the face's largest triangle fanned from the first node of its loop,
/// counter-clockwise seen from outside), up to 1e-10 of the face's size: a piece of an
/// earlier cut has rounded nodes, so its faces are planar only to round-off. Not a side
/// decision of a cut, a check that its construction applies (cut_polyhedral_mesh, split_polyhedral_cells).
bool is_convex_cell(const PolyhedralMesh& mesh, int cell, const std::vector<int>& cell_nodes);

/// The nodes of `cell`'s faces, ascending, each once: what is_convex_cell checks.
std::vector<int> cell_node_set(const PolyhedralMesh& mesh, int cell);

}  // namespace altfem
