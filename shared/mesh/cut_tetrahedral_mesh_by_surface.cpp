// A surface blade's cut of the embedded tetrahedra (cut_tetrahedral_mesh.hpp). The
// fragments are cut as dg's and harmonic's cells are (cut_by_surface_steps: each triangle's
// planar steps on the window of the fragments about it, its pieces joined again a side of
// its plane, so each stays convex), so a step
// splits only the fragments near its triangle and puts its crossing nodes on the faces of
// those it leaves whole. Such a face holds nodes in the middle of its edges, which a fan
// from one of its corners would join by triangles of no area, and the two fragments that
// share it must split it alike: it becomes triangles about its centroid, a new node, as a
// face of the fragments too, so any later cut fans it as itself. Every fragment the steps
// changed is split into tetrahedra afresh by a cone from its centroid (a point strictly
// inside a convex fragment, so no tetrahedron is flat) over its faces' triangles: those
// about a centroid, and a face as it was before the cut fanned from its lowest node, as the
// fragment across it that keeps its tetrahedra fans it. Spreading each step through the
// body instead (the planar cut's way of keeping faces whole) multiplied the fragments by
// every plane of a closed or finely curved blade.
#include <algorithm>
#include <set>

#include "shared/mesh/cone_tetrahedra.hpp"
#include "shared/mesh/cut_by_surface.hpp"
#include "shared/mesh/cut_tetrahedral_mesh.hpp"
#include "shared/mesh/cut_tetrahedral_parts.hpp"
#include "shared/mesh/surface_cut_debris.hpp"

namespace altfem {
namespace {

using namespace tetrahedral_cut;

// Per face of `cut`, whether it is a face of `before` as it was: each node one of
// `before`'s or a copy of one (`origin`), and the set of them one of `before`'s faces'.
std::vector<bool> faces_as_before(const PolyhedralMesh& before, const PolyhedralMesh& cut,
                                  const std::vector<int>& origin) {
  std::set<std::vector<int>> faces;
  for (const std::vector<int>& loop : before.faces) {
    std::vector<int> key = loop;
    std::sort(key.begin(), key.end());
    faces.insert(std::move(key));
  }
  std::vector<bool> kept(static_cast<std::size_t>(cut.face_count()), false);
  std::vector<int> key;
  for (int face = 0; face < cut.face_count(); ++face) {
    key.clear();
    for (const int node : cut.faces[face]) key.push_back(origin[node]);
    if (std::find(key.begin(), key.end(), -1) != key.end()) continue;
    std::sort(key.begin(), key.end());
    kept[face] = faces.count(key) > 0;
  }
  return kept;
}

}  // namespace

TetrahedralCut cut_tetrahedral_mesh_by_surface(const FragmentedTetrahedra& input, const SurfaceBlade& blade) {
  TetrahedralCut result;
  const CutInput fragments = cut_input(input, result.flat_tetrahedra);
  std::vector<int> origin;
  PolyhedralCut cut = cut_by_surface_steps(fragments.mesh(), blade, &origin);
  // Faces of rounding area where the blade's triangles meet would hold its two sides
  // together at a point: opened, as dg's and harmonic's (surface_cut_debris.hpp). Their
  // nodes' copies are new nodes here.
  const FacesSeparated rounding = separate_faces_of_rounding_area(cut.mesh, blade);
  origin.resize(static_cast<std::size_t>(cut.mesh.nodes.rows()), -1);
  result.joined_fragments = cut.joined_cells;
  result.separated_faces = cut.separated_faces + rounding.faces;
  result.duplicated_nodes = cut.duplicated_nodes + rounding.duplicated_nodes;
  result.snapped_nodes = cut.snapped_nodes;

  // Pieces of rounding volume that nothing joins (surface_cut_debris.hpp): their
  // functions would hold no mass. Left without tetrahedra, their rounding of volume lost.
  const std::vector<bool> sliver = isolated_slivers(cut.mesh, cut.parent_cell, fragments.mesh());
  result.dropped_fragments = static_cast<int>(std::count(sliver.begin(), sliver.end(), true));
  const std::vector<bool> as_before = faces_as_before(fragments.mesh(), cut.mesh, origin);
  std::vector<int> copied(origin.size());
  for (std::size_t node = 0; node < origin.size(); ++node)
    copied[node] = origin[node] >= 0 ? fragments.input_node_of(origin[node]) : -1;
  const std::vector<bool> inside = inside_fragments(input, fragments);
  std::vector<int> pieces_of(fragments.tetrahedra.size(), 0);
  for (const int parent : cut.parent_cell) ++pieces_of[parent];
  const auto unchanged = [&](int piece, int parent) {
    const std::vector<int>& faces = cut.mesh.cell_faces[piece];
    return pieces_of[parent] == 1 && faces.size() == fragments.mesh().cell_faces[parent].size() &&
           std::all_of(faces.begin(), faces.end(), [&](int face) { return as_before[face]; });
  };
  std::vector<TetrahedronRow> rows;
  std::vector<std::pair<int, int>> copy_of;
  std::vector<bool> changed = as_before;
  changed.flip();
  ConeTetrahedra cones(cut.mesh, changed);
  FragmentedTetrahedra& output = result.result;
  for (int piece = 0; piece < cut.mesh.cell_count(); ++piece) {
    const int parent = cut.parent_cell[piece];
    const std::size_t first_row = rows.size();
    const bool carried =
        sliver[piece] || (unchanged(piece, parent) && carry_tetrahedra(cut.mesh, piece, copied, inside, input.mesh,
                                                                       fragments.tetrahedra[parent], rows, copy_of));
    if (!carried) cones.split(piece, true, rows, result.flat_tetrahedra);
    output.fragment.insert(output.fragment.end(), rows.size() - first_row, piece);
    result.parent_fragment.push_back(fragments.fragment[parent]);
  }
  for (const int pieces : pieces_of) result.crossed_fragments += pieces > 1 ? 1 : 0;
  cones.set_faces_of(cut.mesh);
  set_result(output, std::move(cut.mesh), cones.added(), rows);
  return result;
}

}  // namespace altfem
