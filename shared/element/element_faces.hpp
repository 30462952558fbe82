#pragma once
// The faces of the reference cells by their corner nodes (VTK order), each counter-
// clockwise seen from outside the cell, so that consecutive corners give the outward
// normal by the right-hand rule. Triangles have 3 corners (the 4th entry is -1).
#include <array>
#include <span>

#include "shared/element/element_type.hpp"

namespace altfem {

inline constexpr std::array<std::array<int, 4>, 4> tetrahedron_faces{
    {{0, 2, 1, -1}, {0, 1, 3, -1}, {1, 2, 3, -1}, {0, 3, 2, -1}}};
inline constexpr std::array<std::array<int, 4>, 6> hexahedron_faces{
    {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};

/// The outward corner lists of a shape's faces.
inline std::span<const std::array<int, 4>> element_faces(ElementShape shape) {
  if (shape == ElementShape::tetrahedron) return tetrahedron_faces;
  return hexahedron_faces;
}

/// Corners per face: 3 (triangles) or 4 (quadrilaterals).
inline int face_corner_count(ElementShape shape) { return shape == ElementShape::tetrahedron ? 3 : 4; }

}  // namespace altfem
