#pragma once
// A surface blade's cut made lean again (cut_by_surface.hpp). Its steps split faces by
// planes that only a few cells need, and the pieces of a cell that the blade did not part
// are joined again: the joined cell keeps every face piece and every node the steps put
// on its faces. Harmonic elements take a degree of freedom per node and dg a face integral
// per face, so the faces that lie in one plane between the same two cells become one face
// again and the nodes in the middle of a straight edge go (Martin et al. 2008 §8 make only
// the cut elements new; the rest of the mesh should not pay for the steps).
#include <vector>

#include "shared/mesh/polyhedral_mesh.hpp"

namespace altfem {

/// Merges the faces between the same two cells (or of one cell's boundary) that share an
/// edge and lie in one plane — every node within `tolerance` of the plane of the group's
/// largest face — into one face, oriented as that face. A group whose union is not one
/// simple loop (a ring, faces that touch at a node only) is left as it was. Nodes no face
/// uses then stay. `fixed` (optional, #faces): faces never merged. Geometry left stale.
/// Returns the number of faces merged away.
int merge_coplanar_faces(PolyhedralMesh& mesh, double tolerance, const std::vector<bool>* fixed = nullptr);

/// Removes every node that, in each face holding it, lies between its two neighbours
/// along the loop within `tolerance` of the segment joining them (a face keeps at least
/// three nodes): a node in the middle of a straight edge, which all the faces along that
/// edge hold alike, so the mesh stays conforming. The node stays, used by no face. Only
/// nodes from `first_node` on are removed. Geometry left stale. Returns the number of
/// nodes removed.
int drop_straight_run_nodes(PolyhedralMesh& mesh, double tolerance, Eigen::Index first_node = 0);

}  // namespace altfem
