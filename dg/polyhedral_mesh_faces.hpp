#pragma once
// A PolyhedralMesh as the DG linear system takes it: each cell as a standalone
// polyhedron and each face once, with its polygon, unit normal and neighbours.
#include <vector>

#include "dg/dg_linear_system.hpp"
#include "shared/mesh/polyhedral_mesh.hpp"

namespace altfem::dg {

/// cell_polyhedron of every cell (#cells).
std::vector<Polyhedron> mesh_cells(const PolyhedralMesh& mesh);
/// Every face (#faces, in mesh order): minus = face_cells(f, 0), plus = face_cells(f, 1),
/// the normal out of the minus cell; no Dirichlet condition (condition −1).
std::vector<DgFace> mesh_faces(const PolyhedralMesh& mesh);

}  // namespace altfem::dg
