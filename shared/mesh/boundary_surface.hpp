#pragma once
#include <vector>

#include "shared/mesh/surface_mesh.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem {

struct BoundarySurface {
  SurfaceMesh surface;          ///< outward triangles through the cells' corner nodes
  std::vector<int> mesh_nodes;  ///< #vertices: surface vertex i is mesh node mesh_nodes[i]
  std::vector<int> cells;       ///< #triangles: the cell each triangle bounds
};

/// The faces that belong to exactly one cell, as outward triangles (hex faces split
/// in two). Higher-order nodes are not used: the result is the straight-sided
/// boundary through the corners.
BoundarySurface boundary_surface(const VolumeMesh& mesh);

}  // namespace altfem
