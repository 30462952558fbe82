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
  /// one whose sides do not close into manifolds after rounding (the next blade tries it again)}, and
  /// "blades_cut_again": how many earlier blades the surface from before them was cut with again, with this one.
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
/// as it is. Where it must leave a piece whole that an earlier finite blade notched (its
/// caps lie on one another), the surface from before that blade
/// (SurfaceMesh::cut_record) is cut again with the blades since and this one: the whole
/// planes one after the other, then the polygons that span a piece's section, then the
/// others at once, each piece by one corefinement with all those that cross it — a
/// sweep's earlier blades left out, since its later ones cover them — or, where blades that
/// cross it meet one another (an X, a T or a V of notches, inside the body or beyond it),
/// refined along each and its caps joined to it by how they turn about each edge
/// (cut_surface_pieces.hpp). So a second notch, a notch that meets the first, a plane across
/// notches, and each cut of a sweep open the surface; the record goes on from the surface
/// before the first finite blade for as long as one may have left a notch. The output then
/// keeps that surface's vertices at their indices and appends what its cut adds (what the
/// cuts since added is gone). Blades that overlap in one plane (two of one plane that are
/// not one sweep's) leave the piece whole, counted.
SurfaceCut cut_surface(const SurfaceMesh& surface, const CuttingPlane& blade);

}  // namespace altfem
