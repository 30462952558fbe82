#pragma once
// A point of a polyhedron's kernel — the points that see its whole boundary from inside,
// the intersection of the inner half-spaces of its face planes — as far from those planes
// as possible (its Chebyshev centre, a small linear program, COIN-OR Clp). A cone
// decomposition about such a point has only positive tetrahedra (polyhedron_rule).
#include <Eigen/Core>
#include <optional>

#include "shared/geometry/polyhedron.hpp"

namespace altfem {

/// The kernel's Chebyshev centre, or nullopt when the kernel has no interior (the
/// polyhedron is not star-shaped, or only about points on its boundary: the largest
/// ball in the kernel has a radius ≤ 1e-9 times the polyhedron's size).
std::optional<Eigen::Vector3d> polyhedron_kernel_point(const Polyhedron& polyhedron);

}  // namespace altfem
