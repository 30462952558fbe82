#pragma once
// What cut_surface's two ways of cutting a closed piece share (issue #33): the whole
// plane's split (cut_surface_by_plane.cgal.cpp) and a polygon's corefinement
// (cut_surface_by_polygon.cgal.cpp). Only cut_surface's CGAL files include it.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "shared/mesh/cut_curve_cleanup.hpp"
#include "shared/mesh/cutting_plane.hpp"
#include "shared/mesh/split_surface_by_plane.hpp"

namespace altfem::surface_cut {

using cut_curve::Mesh;
using cut_curve::Point;
using cut_curve::point_of;
using cut_curve::vector_of;

// What cutting the pieces adds to the surface: vertices after the input's, triangles in
// the output's numbering, the vertices on the cut.
struct CutPieces {
  Eigen::Index input_count = 0;
  std::vector<Eigen::Vector3d> added;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> cut_vertices;
  int cap_triangles = 0;
};

/// The closed `piece` cut by the whole plane of `exact`, both sides appended to `out`;
/// false, appending nothing, when the plane only grazes it (a side of no volume). Throws
/// when a side does not close. `edge_length`: the caps' edges.
bool cut_piece_by_plane(TrianglePiece piece, const ExactBlade& exact, double edge_length, CutPieces& out);

/// `mesh` renumbered by position (its vertices, then its faces by their vertices): CGAL's
/// corefinement numbers what it makes in an order that follows heap addresses, which differ
/// from run to run, and what is built from its order (a cap's remeshing, the cut's new
/// vertices) with it.
void renumber_by_position(Mesh& mesh);

/// The closed `piece` cut by `blades` (each as triangles, not clipped; `planar` per blade:
/// a polygon's, whose cap is remeshed in its plane) that meet one another, inside the body
/// or beyond it, so that no one corefinement splits by them all: the piece refined along
/// their curves, the caps along where they meet, each triangle joined to those that bound
/// the same material across each edge (cut_surface_by_meeting_blades.cgal.cpp); appended to
/// `out`, or false, appending nothing, where no blade reaches inside. Throws
/// std::runtime_error where the triangles about an edge do not alternate between material
/// and void (blades that overlap in one plane).
bool cut_piece_by_meeting_blades(Mesh& piece, const std::vector<Mesh>& blades, const std::vector<bool>& planar,
                                 double edge_length, CutPieces& out);

/// The closed, self-intersection-free `piece` cut by `blades` at once — polygons, whose
/// caps are remeshed in their planes, and triangulated surfaces, whose caps keep their
/// triangles clipped to the body (a vertex where one bends one copy per side) — with one
/// corefinement, appended to `out`; false, appending nothing, when only surface blades
/// are given and none crosses the piece. `piece` is split in the process. Blades that meet
/// one another go to cut_piece_by_meeting_blades.
bool cut_piece_by_blades(Mesh& piece, const std::vector<const CuttingPlane*>& blades, double edge_length,
                         CutPieces& out);

}  // namespace altfem::surface_cut
