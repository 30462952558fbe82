#pragma once
// Bounding-box subdivision (Martin et al. 2008, §6: "bounding box subdivision and Gaussian
// quadrature"): the polyhedron's axis-aligned bounding box split into 2^levels boxes per
// axis; each box whose centre lies inside the polyhedron (generalised winding number > ½)
// keeps a tensor Gauss–Legendre rule, the others are dropped. Positive weights and points
// that need no decomposition of the cell, but only the boxes wholly inside are integrated
// exactly: the boxes the boundary cuts are kept or dropped whole, an error O(h) in the box
// size h for a boundary at an angle to the axes (exact when every face lies on box faces).
#include "shared/geometry/polyhedron.hpp"
#include "shared/quadrature/polyhedron_rule.hpp"

namespace altfem {

/// The rule above: tensor_hex_rule(strength) on each kept box of the 2^levels per axis.
/// points: #kept boxes · n³ × 3 (n = gauss_point_count(strength)); weights sum to the
/// kept boxes' volume; empty when no box centre is inside (a cell thinner than a box).
/// Throws std::invalid_argument for a polyhedron without faces, levels < 0 or > 10, or
/// strength < 0.
PolyhedronRule polyhedron_subdivision_rule(const Polyhedron& polyhedron, int strength, int levels);

}  // namespace altfem
