#pragma once
// Two polygon blades of one plane that overlap (two cut events' notches, one above the
// other): their caps on the surface lie on one another, which no corefinement cuts and no
// join of triangles across edges orders (cut_surface_by_meeting_blades), so cut_surface
// would leave the piece whole. Where their union is convex it is one blade, and cutting by
// it is cutting by both.
#include <optional>

#include "shared/mesh/cutting_plane.hpp"

namespace altfem {

/// The union of the polygons of `a` and `b` as one blade (`b`'s other fields), where both
/// lie in one plane (every corner of `b` within 1e-9 of the polygons' size off `a`'s
/// plane), they overlap (by more than a corner or an edge: decided exactly in `a`'s plane)
/// and their union is convex (exactly); nullopt otherwise. Its corners are theirs, corners
/// where the union runs straight on left out.
std::optional<CuttingPlane> convex_union_blade(const CuttingPlane& a, const CuttingPlane& b);

}  // namespace altfem
