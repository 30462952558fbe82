#pragma once
// A polyhedral mesh as a VTK unstructured grid of VTK_POLYHEDRON (42) cells.
#include "shared/io/unstructured_grid.hpp"
#include "shared/mesh/polyhedral_mesh.hpp"

namespace altfem {

/// The mesh's nodes as points and every cell as a VTK_POLYHEDRON whose faces are the
/// cell's face loops oriented outward from that cell; cell data "volume" (#cells × 1)
/// and "kind" (#cells × 1, the PolyhedralCellKind value). Polyhedron-only, so meshio reads it.
UnstructuredGrid grid_from_polyhedral_mesh(const PolyhedralMesh& mesh);

}  // namespace altfem
