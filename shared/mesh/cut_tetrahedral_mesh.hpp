#pragma once
// A tetrahedral mesh cut by a planar blade: the embedded tetrahedra of the finite cell
// method (Longva et al. 2020 §4.5) after a cut event (issue #33). The mesh is cut as a
// polyhedral mesh (cut_polyhedral_mesh: exact side decisions, nodes on the blade
// duplicated per side), then each piece is split back into tetrahedra: a cone from its
// lowest-numbered node over the faces that do not hold it, each face fanned from its own
// lowest-numbered node. A face is the same polygon for the two pieces that share it, so
// both fan it alike and the result is conforming; a face holding the cone's apex is
// fanned from it (it is that face's lowest node too), so the rule is consistent there.
// A sliver — a tetrahedron of the input or of a cone not positively oriented, or with a
// volume under 1e-14 of its longest edge cubed — is left out (counted), so every piece
// has a positive rounded volume and the result can be cut again; the mesh stays
// conforming up to those slivers.
#include <vector>

#include "shared/mesh/cut_polyhedral_mesh.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem {

struct TetrahedralCut {
  VolumeMesh mesh;                       ///< Tet4, positively oriented, nodes renumbered
  std::vector<int> parent_tetrahedron;   ///< #cells of `mesh`: the input tetrahedron it lies in
  std::vector<NodeSource> node_sources;  ///< #nodes of `mesh`, in the input's numbering
  int crossed_tetrahedra = 0;            ///< input tetrahedra split into two pieces
  int joined_tetrahedra = 0;             ///< of those, the ones whose pieces stay joined (finite blades)
  int separated_faces = 0;               ///< interior input faces in the plane, now two boundary faces
  int duplicated_nodes = 0;              ///< copies of nodes on the opened faces
  int snapped_nodes = 0;                 ///< nodes within 1e-13 of the diagonal of the plane, taken on it
  int flat_tetrahedra = 0;               ///< slivers of the input or of the pieces' cones, left out
};

/// Cuts the Tet4 mesh `mesh` (conforming: neighbours share node indices) by `plane`. A
/// tetrahedron the plane does not cross keeps its row (its nodes renumbered, a node on
/// the blade taken as its copy on the tetrahedron's side); a crossed one becomes the
/// tetrahedra of its two pieces. Nodes no cell uses are dropped. Throws
/// std::invalid_argument for another element type or a zero normal.
TetrahedralCut cut_tetrahedral_mesh(const VolumeMesh& mesh, const CuttingPlane& plane);

}  // namespace altfem
