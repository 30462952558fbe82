#include "shared/mesh/join_cut_pieces.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <utility>

#include "shared/mesh/disjoint_sets.hpp"
#include "shared/mesh/merge_slivers.hpp"

namespace altfem {

namespace {

// Per parent, the pairs of its pieces that hold the two sides of a slit: boundary faces at
// the same positions (the blade's separation opened the face between them).
std::map<int, std::vector<std::pair<int, int>>> slits_by_parent(const PolyhedralMesh& mesh,
                                                                const std::vector<int>& parent_cell) {
  using FaceKey = std::vector<std::array<double, 3>>;
  std::map<std::pair<int, FaceKey>, int> holder;  // (parent, the face's sorted node positions) → piece
  std::map<int, std::vector<std::pair<int, int>>> slits_of;
  for (int face = 0; face < mesh.face_count(); ++face) {
    if (mesh.face_cells(face, 1) >= 0) continue;
    const int piece = mesh.face_cells(face, 0);
    FaceKey key;
    for (const int node : mesh.faces[face])
      key.push_back({mesh.nodes(node, 0), mesh.nodes(node, 1), mesh.nodes(node, 2)});
    std::sort(key.begin(), key.end());
    const auto [found, inserted] = holder.try_emplace({parent_cell[piece], std::move(key)}, piece);
    if (!inserted) slits_of[parent_cell[piece]].push_back({found->second, piece});
  }
  return slits_of;
}

// Joins the pieces of one parent next to one another through an interior face, face by
// face, where `may_join(first, second, a, b, groups)` (the face's cells, their groups so
// far, and the groups) allows, each group becoming one cell (kind cut) and `parent_cell` renumbered with them.
// `kept_nodes` (optional): per node after, its index before. Returns the pieces joined away.
template <typename MayJoin>
int join_neighbouring_pieces(PolyhedralMesh& mesh, std::vector<int>& parent_cell, const MayJoin& may_join,
                             std::vector<int>* kept_nodes) {
  DisjointSets joined(mesh.cell_count());
  int joined_away = 0;
  for (int face = 0; face < mesh.face_count(); ++face) {
    const int first = mesh.face_cells(face, 0), second = mesh.face_cells(face, 1);
    if (second < 0 || parent_cell[first] != parent_cell[second]) continue;
    const int a = joined.find(first), b = joined.find(second);
    if (a == b || !may_join(first, second, a, b, joined)) continue;
    joined.join(a, b);
    ++joined_away;
  }
  if (joined_away == 0) {
    if (kept_nodes) {
      kept_nodes->resize(static_cast<std::size_t>(mesh.nodes.rows()));
      std::iota(kept_nodes->begin(), kept_nodes->end(), 0);
    }
    return 0;
  }
  std::vector<int> new_cell;
  std::vector<int> kept = merge_cell_groups(mesh, joined, PolyhedralCellKind::cut, &new_cell);
  std::vector<int> parents(static_cast<std::size_t>(mesh.cell_count()));
  for (std::size_t cell = 0; cell < new_cell.size(); ++cell) parents[new_cell[cell]] = parent_cell[cell];
  parent_cell = std::move(parents);
  if (kept_nodes) *kept_nodes = std::move(kept);
  return joined_away;
}

}  // namespace

int join_unparted_pieces(PolyhedralMesh& mesh, std::vector<int>& parent_cell) {
  const std::map<int, std::vector<std::pair<int, int>>> slits_of = slits_by_parent(mesh, parent_cell);
  const auto not_across_a_slit = [&](int first, int, int a, int b, DisjointSets& groups) {
    const auto slits = slits_of.find(parent_cell[first]);
    return slits == slits_of.end() || std::none_of(slits->second.begin(), slits->second.end(), [&](const auto& pair) {
             const int p = groups.find(pair.first), q = groups.find(pair.second);
             return (p == a && q == b) || (p == b && q == a);
           });
  };
  return join_neighbouring_pieces(mesh, parent_cell, not_across_a_slit, nullptr);
}

int join_pieces_by_side(PolyhedralMesh& mesh, std::vector<int>& parent_cell, const CuttingPlane& plane,
                        std::vector<int>* kept_nodes) {
  // A piece's side: its node farthest from the plane's (the nodes a step took on the plane
  // may round to either side of it).
  const ExactBlade exact(plane);
  std::vector<int> side(static_cast<std::size_t>(mesh.cell_count()), 0);
  for (int piece = 0; piece < mesh.cell_count(); ++piece) {
    double farthest = -1;
    int node_farthest = -1;
    for (const int face : mesh.cell_faces[piece])
      for (const int node : mesh.faces[face]) {
        const double distance = std::abs((mesh.nodes.row(node).transpose() - plane.point).dot(plane.normal));
        if (distance > farthest) farthest = distance, node_farthest = node;
      }
    side[piece] = exact.side(mesh.nodes.row(node_farthest).transpose());
  }
  const std::map<int, std::vector<std::pair<int, int>>> slits_of = slits_by_parent(mesh, parent_cell);
  const auto one_side_or_unparted = [&](int first, int second, int, int, DisjointSets&) {
    return side[first] == side[second] || slits_of.count(parent_cell[first]) == 0;
  };
  return join_neighbouring_pieces(mesh, parent_cell, one_side_or_unparted, kept_nodes);
}

}  // namespace altfem
