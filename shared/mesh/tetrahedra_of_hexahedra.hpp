#pragma once
// A conforming Tet4 mesh of a hexahedral mesh, for what needs tetrahedra of a geometry
// given as hexahedra (fcm's embedded mesh, issue #35).
//
// Each quadrilateral face is split by the diagonal through its corner of smallest global
// index, a rule both cells sharing the face apply alike, so the triangulation conforms
// without looking at neighbours; each face triangle and the cell's corner centroid make a
// tetrahedron: 12 per hexahedron, positively oriented for every cell star-shaped about its
// centroid (every convex one). The min-index rule alone cannot split every hexahedron into
// tetrahedra without an inner point (Dompierre et al. 1999, "How to subdivide pyramids,
// prisms and hexahedra into tetrahedra"); the centroid is that point, always.
#include "shared/mesh/volume_mesh.hpp"

namespace altfem {

/// The tetrahedra of the cells of `hexahedra` (Hex8, Hex20 or Hex27: corners only, so
/// curved cells become straight-sided). Nodes: the mesh's corner nodes in their order,
/// then one centroid per cell. Cells: 12 per hexahedron, cell c's at rows 12c … 12c+11.
/// Throws InputError naming the cell when a tetrahedron would not be positive (a cell
/// not star-shaped about its centroid).
VolumeMesh tetrahedra_of_hexahedra(const VolumeMesh& hexahedra);

}  // namespace altfem
