#pragma once
// Gmsh's element type numbers, their node counts and dimensions, and the
// permutation from Gmsh's node order to VTK's (docs/conventions.md, "Numerical conventions").
#include <optional>
#include <span>
#include <string_view>

#include "shared/element/element_type.hpp"

namespace altfem {

struct GmshElementType {
  int number;                              ///< Gmsh's element type number, e.g. 4 for a 4-node tetrahedron
  int nodes;                               ///< nodes per element
  int dimension;                           ///< 0 point, 1 line, 2 surface, 3 volume
  std::string_view name;                   ///< Gmsh's description, for messages
  std::optional<ElementType> altfem_type;  ///< nullopt: altfem does not read this cell
};

/// The entry for a Gmsh type number; nullptr for an unknown number.
const GmshElementType* gmsh_element_type(long long number);

/// For an altfem type, `order[v]` is the Gmsh node index stored at VTK index v
/// (length element_node_count(type)).
std::span<const int> gmsh_to_vtk_order(ElementType type);

}  // namespace altfem
