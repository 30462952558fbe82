#include "shared/element/element_type.hpp"

#include <array>

namespace altfem {

namespace {
struct ElementFacts {
  ElementType type;
  std::string_view name;
  ElementShape shape;
  int nodes;
  int corners;
  int degree;
  int vtk_type;
};

constexpr std::array<ElementFacts, 6> facts{{
    {ElementType::tet4, "tet4", ElementShape::tetrahedron, 4, 4, 1, 10},
    {ElementType::tet10, "tet10", ElementShape::tetrahedron, 10, 4, 2, 24},
    {ElementType::tet20, "tet20", ElementShape::tetrahedron, 20, 4, 3, 71},
    {ElementType::hex8, "hex8", ElementShape::hexahedron, 8, 8, 1, 12},
    {ElementType::hex20, "hex20", ElementShape::hexahedron, 20, 8, 2, 25},
    {ElementType::hex27, "hex27", ElementShape::hexahedron, 27, 8, 2, 29},
}};

const ElementFacts& facts_of(ElementType type) { return facts[static_cast<int>(type)]; }
}  // namespace

std::string_view element_name(ElementType type) { return facts_of(type).name; }

std::optional<ElementType> element_type_from_name(std::string_view name) {
  for (const auto& entry : facts)
    if (entry.name == name) return entry.type;
  return std::nullopt;
}

ElementShape element_shape(ElementType type) { return facts_of(type).shape; }
int element_node_count(ElementType type) { return facts_of(type).nodes; }
int element_corner_count(ElementType type) { return facts_of(type).corners; }
int element_degree(ElementType type) { return facts_of(type).degree; }
int element_vtk_cell_type(ElementType type) { return facts_of(type).vtk_type; }

}  // namespace altfem
