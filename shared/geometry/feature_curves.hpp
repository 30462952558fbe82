#pragma once
// Sharp-edge curves of CSG shapes, for Mesh_3 to protect (AnalyticShape::sharp_edges):
// where a child's edge stays on the CSG's surface, and where a child's planar face meets
// another child's surface (the rim of a half-ball, the end of a cylinder cut by a box).
#include <vector>

#include "shared/geometry/analytic_shape.hpp"

namespace altfem {

/// The parts of `line` on the surface of `shape`: runs of samples with |φ| ≤ tolerance,
/// each end moved by bisection to where the line leaves the surface (into another child
/// of a union, or out of an intersection or difference). A closed line that stays whole
/// stays closed.
std::vector<Polyline> parts_on_surface(const Polyline& line, const AnalyticShape& shape, double tolerance);

/// The curves where `other`'s surface crosses the rectangle `face`: marching squares of
/// other's level set on a grid of at most `spacing`, every point found by bisection along
/// its grid edge (so it lies on the face and on the zero set), chained into polylines —
/// closed where the curve closes inside the face, open where it leaves it. Curves smaller
/// than the spacing may be missed.
std::vector<Polyline> zero_set_on_face(const PlanarFace& face, const AnalyticShape& other, double spacing);

/// Makes polyline ends closer than `tolerance` identical (the first one found wins).
void snap_ends(std::vector<Polyline>& lines, double tolerance);

}  // namespace altfem
