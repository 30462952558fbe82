#pragma once
// A closed triangle surface split by a whole plane into its two sides, each closed by its
// cap (cut_surface, issue #33). Only cut_surface's CGAL files include it.
#include <array>
#include <optional>
#include <vector>

#include "shared/mesh/cut_curve_cleanup.hpp"
#include "shared/mesh/cutting_plane.hpp"

namespace altfem {

/// A closed piece of a surface as arrays: its points with their "v:input" and its
/// triangles (indices into points), consistently oriented.
struct TrianglePiece {
  std::vector<cut_curve::Point> points;
  std::vector<int> input;
  std::vector<std::array<int, 3>> triangles;
};

struct PlaneSplit {
  std::array<cut_curve::Mesh, 2> sides;
  std::vector<int> inputs_on_plane;  ///< sorted "v:input" of the piece's vertices taken on the plane
  bool grazes = false;               ///< the vertices taken on it leave none on one side: no sides
};

/// The sides of the closed, consistently oriented `piece`
/// below and above the plane of `blade`: [0] the negative side, [1] the positive one, each
/// closed and outward.
/// - Which side a vertex lies on is `blade.side`, an exact predicate, so a plane through
///   vertices, along edges or in faces is an ordinary case; a face in the plane goes to the
///   side its material lies on (below it when it faces along the normal).
/// - A vertex within `snap` of where the plane crosses one of its edges is taken on the
///   plane (no point moves, both sides agree): no cluster of crossing points at a vertex
///   the plane passes within rounding of.
/// - An edge with ends strictly on either side gets one crossing point, rounded once and
///   shared by both sides and by both faces holding the edge; the faces it crosses fall into
///   their convex pieces, as fans.
/// - Each side is closed by a cap: the constrained Delaunay triangulation of its border
///   loops in the plane, inside by the loops' nesting, facing away from its material.
/// - Where a section touches itself (a valley's edge or a vertex in the plane with the cap
///   on both sides), each face pairs with the one behind it, an exact orientation, and the
///   point gets a vertex per fan of faces: the two sides of the touch separate.
/// Vertices carry "v:input" (−1 for crossing points); the input's vertices on the plane are
/// in both sides. Nothing when a side does not close into a manifold surface (border loops
/// that cross or meet after rounding, an edge whose faces cannot be paired): the caller
/// leaves the piece whole.
///
/// Written here rather than taken from CGAL 5.5 (Debian 12's): its `clip` with a plane
/// corefines the surface with a box through exact constructions, several times the cost of
/// this for the pencil's every cut (docs/performance.md, "Cuts"), and it closed a prism
/// cut along a valley's edge into one piece of the wrong volume (test_split_surface_by_plane.cpp).
std::optional<PlaneSplit> split_surface_by_plane(TrianglePiece piece, const ExactBlade& blade, double snap);

}  // namespace altfem
