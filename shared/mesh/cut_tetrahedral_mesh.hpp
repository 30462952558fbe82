#pragma once
// A tetrahedral mesh cut by a planar blade: the embedded tetrahedra of the finite cell
// method (Longva et al. 2020 §4.5) after a cut event (issue #33).
//
// The tetrahedra fill convex fragments (at first each tetrahedron is its own). A cut cuts
// the fragments as a polyhedral mesh (cut_polyhedral_mesh: exact side decisions, nodes on
// the blade duplicated per side): a crossed fragment becomes its two convex pieces, each
// split into tetrahedra afresh — a cone from its lowest node over the faces that do not
// hold it, each face fanned from its own lowest node, "lowest" by position
// (lexicographic coordinates, which no cut changes). A fragment the blade misses keeps its
// tetrahedra bit for bit. A face is the same polygon for the fragments that share it and
// both fan it from the same node, whenever each was split, so the mesh stays conforming.
//
// Cutting fragments instead of tetrahedra is what keeps repeated cuts affordable: a
// fragment is a tetrahedron cut by half-spaces, so however often it is cut its pieces are
// convex with a face per blade, while a tetrahedron's pieces split into tetrahedra and cut
// again multiply by about three per cut (a pencil sharpened 12 times near its tip went from
// 490 to 13,500 tetrahedra).
//
// A sliver — a tetrahedron of the input or of a cone not positively oriented, or with a
// volume under 1e-14 of its longest edge cubed — is left out (counted), so every piece
// has a positive rounded volume and the result can be cut again; a fragment left with no
// tetrahedron is dropped before the next cut. The mesh stays conforming up to those slivers.
#include <vector>

#include "shared/mesh/cut_polyhedral_mesh.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem {

/// Tet4 cells grouped into the convex polyhedra they fill.
struct FragmentedTetrahedra {
  VolumeMesh mesh;  ///< Tet4, positively oriented, conforming by node
  /// Convex cells on mesh.nodes, conforming (geometry arrays empty); empty: each
  /// tetrahedron of `mesh` is its own fragment.
  PolyhedralMesh fragments{};
  std::vector<int> fragment{};  ///< #cells of `mesh` (empty with `fragments`): the fragment it lies in

  int fragment_count() const;
  int fragment_of(int tetrahedron) const { return fragment.empty() ? tetrahedron : fragment[tetrahedron]; }
};

struct TetrahedralCut {
  FragmentedTetrahedra result;
  std::vector<int> parent_fragment;  ///< #fragments of `result`: the input's fragment it lies in
  /// Per node of `result.mesh` but the cones' centroids appended after them (cone_tetrahedra.hpp
  /// in cut_tetrahedral_parts.hpp), in the input's numbering; empty for a surface blade's cut.
  std::vector<NodeSource> node_sources;
  int crossed_fragments = 0;  ///< input fragments split into two pieces
  int joined_fragments = 0;   ///< of those, the ones whose pieces stay joined (finite blades)
  int separated_faces = 0;    ///< interior fragment faces in the plane, now two boundary faces
  int duplicated_nodes = 0;   ///< copies of nodes on the opened faces
  int snapped_nodes = 0;      ///< nodes within 1e-13 of the diagonal of the plane, taken on it
  int flat_tetrahedra = 0;    ///< slivers of the input or of the pieces' cones, left out
  int dropped_fragments = 0;  ///< surface blades: fragments of rounding volume cut off whole, left without tetrahedra
};

/// The cells of `cells` (convex, with planar faces: a grid's hexahedra) as fragments, each
/// split into tetrahedra as a cut splits a piece (a cone from its first node by position),
/// so the tetrahedra conform wherever the cells do: a hexahedron's 6, without the inner
/// point tetrahedra_of_hexahedra adds (the cone's apex is the first node of every face it
/// lies on, so every face is fanned from its first node). Its slivers are left out.
FragmentedTetrahedra convex_cells_as_fragments(PolyhedralMesh cells);

/// Cuts `input` by `plane` (with `scope`, one step of a surface blade's: CutScope). A
/// fragment the plane does not cross keeps its tetrahedra (each corner taken as the copy
/// this fragment holds, for a node on the blade); a crossed one becomes the tetrahedra of
/// its two pieces. A split step must spread (CutScope::spread). Throws
/// std::invalid_argument for another element type or a zero normal. A blade with a
/// `surface` is cut_tetrahedral_mesh_by_surface's.
TetrahedralCut cut_tetrahedral_mesh(const FragmentedTetrahedra& input, const CuttingPlane& plane,
                                    const CutScope& scope = {});

/// `input` cut by every step of `blade` (cut_by_surface_steps: the steps split only the
/// fragments near each triangle), each fragment the steps changed split into tetrahedra
/// afresh by a cone from its centroid, a face the steps changed into triangles about its
/// centroid (cut_tetrahedral_mesh_by_surface.cpp says why); the others keep their
/// tetrahedra. Its parent fragments are `input`'s, its node sources empty, its counts the
/// steps' summed (crossed_fragments: fragments of `input` now in several).
TetrahedralCut cut_tetrahedral_mesh_by_surface(const FragmentedTetrahedra& input, const SurfaceBlade& blade);

}  // namespace altfem
