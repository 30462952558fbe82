#pragma once
// Where a point lies with respect to the cells of a polyhedral mesh, convex or not (cut
// cells of a sliced mesh, merged slivers): the generalised winding number of a closed
// polyhedron (shared/geometry/polyhedron_winding_number) and the distance to a cell's
// boundary. What the polyhedral methods' embedding evaluators locate the embedded
// surface's points with.
#include <Eigen/Core>

#include "shared/geometry/polyhedron.hpp"
#include "shared/geometry/polyhedron_winding_number.hpp"  // winding_number
#include "shared/mesh/polyhedral_mesh.hpp"

namespace altfem {

/// Distance from x to the boundary of `cell`: to the nearest of its planar face polygons
/// (convex or not).
double distance_to_cell_boundary(const PolyhedralMesh& mesh, int cell, const Eigen::Vector3d& x);

/// x inside `cell` (winding number > 1/2) or within `tolerance` of its boundary. A convex
/// cell (convex_kind) is decided by its face planes alone, a non-convex one by them where
/// they can (x behind all of them).
bool cell_holds(const PolyhedralMesh& mesh, int cell, const Eigen::Vector3d& x, double tolerance);

}  // namespace altfem
