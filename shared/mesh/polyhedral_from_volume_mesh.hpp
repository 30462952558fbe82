#pragma once
// Conversion of a tetrahedral or hexahedral volume mesh into a polyhedral mesh, so every
// scene's mesh runs with the polyhedral methods (DG, harmonic).
#include "shared/mesh/polyhedral_mesh.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem {

/// Every cell becomes a polyhedron with its corner nodes (higher-order nodes are dropped:
/// the cells are taken straight-sided) and its 4 triangles or 6 quadrilaterals as faces;
/// faces shared by two cells are stored once and become interior faces. Nodes used by
/// no corner are dropped and the rest renumbered in their original order. Geometry is
/// computed (compute_polyhedral_geometry).
PolyhedralMesh polyhedral_mesh_from_volume_mesh(const VolumeMesh& mesh);

}  // namespace altfem
