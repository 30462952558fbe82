#pragma once
// What the planes of a surface blade's triangles leave of rounding size where several
// triangles meet (cut_by_surface.hpp): the blade is cut one triangle's plane after
// another, and near a vertex the blade shares among five or six triangles their planes
// cut the cells into pieces a few ulps across. Each pass below removes one kind of such
// debris without moving material: coincident nodes along a face, faces of rounding area
// that would join the two sides of the blade at a point, pieces of rounding volume left
// alone.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "shared/mesh/cut_by_surface.hpp"
#include "shared/mesh/polyhedral_mesh.hpp"

namespace altfem {

/// Nodes at most `tolerance` apart that follow one another along a face — a crossing that
/// rounded onto an end of its edge, or the points where several planes meet, constructed
/// from different edges — become one node (one of them, where it was); a
/// face left with fewer than 3 nodes (no area) is dropped. Nodes keep their indices, the
/// welded ones used by no face. The copies of a node on an opened face never follow one
/// another along a face: they lie on either side of it.
void weld_coincident_neighbours(PolyhedralMesh& mesh, double tolerance = 0);

/// Moves each node from `first_new` on that lies within `tolerance` of one of `corners` (a
/// blade triangle's) exactly onto it. The planes of the triangles that meet at a blade
/// vertex cross the cells' edges near it at points that differ by roundings, which the
/// planes' grazing angles there magnify to 1e-11; left apart, they order along no line,
/// and a face with several of them cannot be split.
void snap_new_nodes_to_corners(PolyhedralMesh& mesh, Eigen::Index first_new,
                               const std::array<Eigen::Vector3d, 3>& corners, double tolerance);

struct FacesSeparated {
  int faces = 0;             ///< interior faces made two boundary faces
  int duplicated_nodes = 0;  ///< copies of their nodes for the pieces that no longer meet there
};

/// Every interior face on `blade` (a node within 1e-9 of the mesh's bounding-box diagonal of
/// it) of rounding width (its area at most its longest edge × 1e-12 of the diagonal, ten
/// times the cut's snapping distance) or size (no edge longer than 1e-9 of it) becomes a boundary
/// face of each of its two cells, and each node of those faces gets a copy for each group
/// of cells that no longer meet around it (duplicate_separated_nodes). Such a face is where
/// pieces of rounding size at a blade vertex, or along an edge between two of its
/// triangles, touch the cells on both sides of the blade: a contact of no area, through
/// which the two sides of a closed blade stayed one body. Geometry left stale.
FacesSeparated separate_faces_of_rounding_area(PolyhedralMesh& mesh, const SurfaceBlade& blade);

/// Drops the cells that no interior face joins to a neighbour and whose volume is at most
/// 1e-13 of their parent cell's (`parent_cell`: per cell, its cell of `parents`; updated),
/// and the nodes no face uses then: slivers a few ulps thin cut off whole, which no
/// neighbour can take in and whose element matrices would be singular. Their volume, a
/// rounding of the body's, is lost (an event's volume_change shows it). Returns how many.
int drop_isolated_slivers(PolyhedralMesh& mesh, std::vector<int>& parent_cell, const PolyhedralMesh& parents);
/// Per cell of `mesh`, whether drop_isolated_slivers drops it.
std::vector<bool> isolated_slivers(const PolyhedralMesh& mesh, const std::vector<int>& parent_cell,
                                   const PolyhedralMesh& parents);

}  // namespace altfem
