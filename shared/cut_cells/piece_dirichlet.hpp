#pragma once
// Dirichlet conditions on topology-aware cells (piece_mesh.hpp). A region selects the
// copies of a node whose material reaches the region, not every copy at the node's
// position: a region at one bar's end must not hold the other bar's copy of a node in
// a cell both bars cross. Nodes with a single copy are selected as nodal_dirichlet does.
#include "shared/cut_cells/piece_mesh.hpp"
#include "shared/fem/nodal_dirichlet.hpp"

namespace altfem {

/// For nodes of `pieces.mesh`: true when the node has one copy, or when a vertex of the
/// material of one of its pieces (the piece's embedded tetrahedra clipped by the cell)
/// lies in the region, within the region's tolerance. Keeps copies of what it needs.
NodeRegionFilter piece_dirichlet_nodes(const PieceMesh& pieces, const VolumeMesh& embedded);

}  // namespace altfem
