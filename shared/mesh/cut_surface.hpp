#pragma once
// The surface a method deforms, cut by a blade in its rest configuration, as the volume
// meshes are (issue #33): it opens along the cut and each side is closed by a cap, the
// blade's part inside the body, so the frames show the body open.
#include <nlohmann/json.hpp>

#include "shared/mesh/cutting_plane.hpp"
#include "shared/mesh/surface_mesh.hpp"

namespace altfem {

struct SurfaceCut {
  /// The input's vertices at their indices, then the new ones: a copy per side of each
  /// point of the cut curve, and the caps' vertices inside the body (a finite blade's
  /// edge there is shared by both caps: the material is not separated beyond it).
  /// Triangles: the input's, those the blade crossed replaced by their pieces, then the
  /// caps (each side's outward: −normal on the blade's positive side). Vertices on the
  /// cut carry `embedding_offsets`.
  SurfaceMesh surface;
  /// {"added_triangles": caps included, "cap_triangles": both sides', "added_vertices", "pieces_left_whole": pieces the
  /// blade crosses but cannot cut: one an earlier finite blade left with its caps on one another (it stays whole), or
  /// one whose sides do not close into manifolds after rounding (the next blade tries it again)}, and for a sweep's
  /// blade "from_before_sweep": whether it cut the surface from before the sweep.
  nlohmann::json facts;
};

/// `surface` (closed, outward, without self-intersections) cut by `blade`: the whole
/// plane, or its convex polygon, and with `blade.piece_at` only the connected piece of
/// the surface nearest that point. A whole plane splits each piece by exact side
/// predicates and closes each side with the constrained Delaunay triangulation of its
/// section (split_surface_by_plane); a polygon's blade goes through CGAL's corefinement
/// (exact predicates and constructions), which also clips the blade to the body. Either
/// way a blade through vertices, along edges or on faces is an ordinary case. Each
/// connected piece is cut on its own; one the blade separates no two vertices of is kept
/// as it is. A blade of a sweep (`blade.sweep`) whose earlier blade cut `surface` cuts the
/// surface from before the sweep instead (SurfaceMesh::before_sweep), so each of a
/// sweep's cuts opens the notch its earlier ones made: the output then keeps that
/// surface's vertices at their indices and appends this cut's (those the sweep's earlier
/// cuts added are gone).
SurfaceCut cut_surface(const SurfaceMesh& surface, const CuttingPlane& blade);

}  // namespace altfem
