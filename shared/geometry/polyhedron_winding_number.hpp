#pragma once
// The generalised winding number of a closed polyhedron (1 inside, 0 outside, ½ on a
// face): the signed solid angles its faces subtend at the point, over 4π. What locates
// points in cells (shared/mesh/polyhedral_cell_location) and keeps the inside points of
// the bounding-box rules (shared/quadrature/polyhedron_subdivision_rule,
// polyhedron_monte_carlo_rule).
#include <Eigen/Core>
#include <vector>

#include "shared/geometry/polyhedron.hpp"

namespace altfem {

/// The solid angle of a planar face loop (indices into the rows of `points`, #points × 3,
/// convex or not) seen from x, by its fan triangles (Van Oosterom & Strackee 1983); signed,
/// positive when the loop turns counter-clockwise seen from x.
double fan_solid_angle(const Eigen::MatrixXd& points, const std::vector<int>& loop, const Eigen::Vector3d& x);

/// Generalised winding number of a closed polyhedron about x (1 inside, 0 outside; by
/// the signed solid angles of each face's fan triangles, exact for non-convex faces).
double winding_number(const Polyhedron& polyhedron, const Eigen::Vector3d& x);

}  // namespace altfem
