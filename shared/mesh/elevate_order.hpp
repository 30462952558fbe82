#pragma once
#include "shared/mesh/volume_mesh.hpp"

namespace altfem {

/// The same cells with the higher-order nodes of `type` (Tet4 → Tet10/Tet20,
/// Hex8 → Hex20/Hex27) placed by the cells' straight (affine or trilinear) map, and
/// shared between neighbouring cells. A node is identified by the corner vertices
/// it interpolates and their weights, so the function needs no edge or face tables:
/// the reference element's node list defines everything.
VolumeMesh elevate_order(const VolumeMesh& linear_mesh, ElementType type);

}  // namespace altfem
