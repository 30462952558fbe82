#include "shared/mesh/gmsh_element_types.hpp"

#include <array>
#include <stdexcept>

namespace altfem {

namespace {
// Gmsh reference manual, section "Node ordering" (MSH element types 1-31, 92, 93).
constexpr std::array<GmshElementType, 33> types{{
    {1, 2, 1, "2-node line", std::nullopt},
    {2, 3, 2, "3-node triangle", std::nullopt},
    {3, 4, 2, "4-node quadrangle", std::nullopt},
    {4, 4, 3, "4-node tetrahedron", ElementType::tet4},
    {5, 8, 3, "8-node hexahedron", ElementType::hex8},
    {6, 6, 3, "6-node prism", std::nullopt},
    {7, 5, 3, "5-node pyramid", std::nullopt},
    {8, 3, 1, "3-node line", std::nullopt},
    {9, 6, 2, "6-node triangle", std::nullopt},
    {10, 9, 2, "9-node quadrangle", std::nullopt},
    {11, 10, 3, "10-node tetrahedron", ElementType::tet10},
    {12, 27, 3, "27-node hexahedron", ElementType::hex27},
    {13, 18, 3, "18-node prism", std::nullopt},
    {14, 14, 3, "14-node pyramid", std::nullopt},
    {15, 1, 0, "1-node point", std::nullopt},
    {16, 8, 2, "8-node quadrangle", std::nullopt},
    {17, 20, 3, "20-node hexahedron", ElementType::hex20},
    {18, 15, 3, "15-node prism", std::nullopt},
    {19, 13, 3, "13-node pyramid", std::nullopt},
    {20, 9, 2, "9-node incomplete triangle", std::nullopt},
    {21, 10, 2, "10-node triangle", std::nullopt},
    {22, 12, 2, "12-node incomplete triangle", std::nullopt},
    {23, 15, 2, "15-node triangle", std::nullopt},
    {24, 15, 2, "15-node incomplete triangle", std::nullopt},
    {25, 21, 2, "21-node triangle", std::nullopt},
    {26, 4, 1, "4-node line", std::nullopt},
    {27, 5, 1, "5-node line", std::nullopt},
    {28, 6, 1, "6-node line", std::nullopt},
    // Gmsh's cubic tetrahedron orders its face nodes unlike VTK's Lagrange tetrahedron;
    // not read until someone needs it.
    {29, 20, 3, "20-node tetrahedron", std::nullopt},
    {30, 35, 3, "35-node tetrahedron", std::nullopt},
    {31, 56, 3, "56-node tetrahedron", std::nullopt},
    {92, 64, 3, "64-node hexahedron", std::nullopt},
    {93, 125, 3, "125-node hexahedron", std::nullopt},
}};

// Gmsh orders hexahedron edges (0,1),(0,3),(0,4),(1,2),(1,5),(2,3),(2,6),(3,7),
// (4,5),(4,7),(5,6),(6,7) and faces z-,y-,x-,x+,y+,z+; VTK orders edges
// (0,1),(1,2),(2,3),(3,0),(4,5),(5,6),(6,7),(7,4),(0,4),(1,5),(2,6),(3,7) and faces
// x-,x+,y-,y+,z-,z+. Tetrahedra: Gmsh's edges 8 and 9 are (2,3) and (1,3), VTK's (1,3) and (2,3).
constexpr std::array<int, 4> tet4_order{0, 1, 2, 3};
constexpr std::array<int, 10> tet10_order{0, 1, 2, 3, 4, 5, 6, 7, 9, 8};
constexpr std::array<int, 8> hex8_order{0, 1, 2, 3, 4, 5, 6, 7};
constexpr std::array<int, 27> hex27_order{0,  1,  2,  3,  4,  5,  6,  7,  8,  11, 13, 9,  16, 18,
                                          19, 17, 10, 12, 14, 15, 22, 23, 21, 24, 20, 25, 26};
}  // namespace

const GmshElementType* gmsh_element_type(long long number) {
  for (const auto& type : types)
    if (type.number == number) return &type;
  return nullptr;
}

std::span<const int> gmsh_to_vtk_order(ElementType type) {
  switch (type) {
    case ElementType::tet4: return tet4_order;
    case ElementType::tet10: return tet10_order;
    case ElementType::hex8: return hex8_order;
    case ElementType::hex20: return std::span<const int>(hex27_order).first(20);
    case ElementType::hex27: return hex27_order;
    case ElementType::tet20: break;
  }
  throw std::logic_error("gmsh_to_vtk_order: Gmsh's tet20 is not read");
}

}  // namespace altfem
