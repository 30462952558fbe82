#pragma once
// Part of a volume mesh: the cells of a grid that a shape holds (an exact tetrahedral mesh
// of a shape built of boxes, fem's grid of such a shape).
#include <vector>

#include "shared/mesh/volume_mesh.hpp"

namespace altfem {

/// The mesh of `cells` (indices into mesh.cells, in that order) with the nodes they use,
/// numbered in the order the cells first use them.
VolumeMesh volume_mesh_cells(const VolumeMesh& mesh, const std::vector<int>& cells);

}  // namespace altfem
