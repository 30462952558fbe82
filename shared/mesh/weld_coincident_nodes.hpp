#pragma once
// Nodes at one position made one node: the tetrahedra a cut and the topology-aware
// cells of cut_cells/ work on must be conforming by node index, not only by position.
#include "shared/mesh/volume_mesh.hpp"

namespace altfem {

/// `mesh` with every set of nodes at exactly the same position made one node (the
/// lowest-numbered; the rest renumbered in order): a mesh read as a soup of tetrahedra
/// becomes conforming by node, which find_cell_pieces and a cut's node copies rely on.
VolumeMesh weld_coincident_nodes(const VolumeMesh& mesh);

}  // namespace altfem
