#pragma once
// The cells of a polyhedral mesh that are plain linear elements: a tetrahedron (4 nodes,
// 4 triangles) or a hexahedron (8 nodes, 6 quadrilaterals) keeps its closed-form Tet4 /
// Hex8 basis in the harmonic method — the linear basis of a tet is its harmonic basis,
// and the MFS basis of a hex approaches the trilinear one (Martin et al. 2008 §5) — so
// only general polyhedra pay for the MFS fit.
#include <optional>
#include <vector>

#include "shared/element/element_type.hpp"
#include "shared/mesh/polyhedral_mesh.hpp"

namespace altfem::harmonic {

struct PlainCell {
  ElementType type;        ///< tet4 or hex8
  std::vector<int> nodes;  ///< global node indices in VTK corner order (4 or 8)
};

/// The Tet4/Hex8 of `cell`, recovered from its faces, if its kind is tetrahedron or
/// hexahedron and its faces have that element's shape; nullopt otherwise.
std::optional<PlainCell> plain_cell(const PolyhedralMesh& mesh, int cell);

/// The global node indices of `cell` in the vertex order of cell_polyhedron(mesh, cell)
/// (first appearance along its face loops).
std::vector<int> cell_nodes(const PolyhedralMesh& mesh, int cell);

}  // namespace altfem::harmonic
