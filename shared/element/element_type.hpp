#pragma once
// The Lagrange element types of the conforming meshes (docs/architecture.md).
// Node order inside altfem is VTK's for every type; readers permute on input.
#include <optional>
#include <string_view>

namespace altfem {

enum class ElementType { tet4, tet10, tet20, hex8, hex20, hex27 };
enum class ElementShape { tetrahedron, hexahedron };

/// The scene-file name of a type: "tet4", "tet10", "tet20", "hex8", "hex20", "hex27".
std::string_view element_name(ElementType type);
/// The inverse of element_name; nullopt for an unknown name.
std::optional<ElementType> element_type_from_name(std::string_view name);
ElementShape element_shape(ElementType type);
int element_node_count(ElementType type);
/// Corner (vertex) nodes come first in VTK order: 4 for tets, 8 for hexes.
int element_corner_count(ElementType type);
/// Polynomial degree of the element's complete polynomial space (1, 2 or 3).
int element_degree(ElementType type);
/// The VTK cell type: 10, 24, 71 (Lagrange tet), 12, 25, 29.
int element_vtk_cell_type(ElementType type);

}  // namespace altfem
