#pragma once
// The corner tetrahedra of a cell, whose signed volumes tell an inverted or flat cell.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <span>

#include "shared/element/element_type.hpp"

namespace altfem {

/// Corner tetrahedra (VTK corner indices) of a positively oriented cell: the cell
/// itself for a tetrahedron; for a hexahedron, each corner with its three edge
/// neighbours in right-handed order (8 tetrahedra).
std::span<const std::array<int, 4>> corner_tetrahedra(ElementShape shape);

/// Six times the signed volume of the tetrahedron (a, b, c, d): det[b-a, c-a, d-a].
inline double six_signed_volume(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                                const Eigen::Vector3d& d) {
  return (b - a).cross(c - a).dot(d - a);
}

}  // namespace altfem
