#include "shared/mesh/simplify_cut_faces.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <map>
#include <numeric>

#include "shared/mesh/disjoint_sets.hpp"

namespace altfem {

namespace {

// A face's unit normal and area.
std::pair<Eigen::Vector3d, double> face_plane(const PolyhedralMesh& mesh, int face) {
  const Eigen::Vector3d area = face_area_vector(mesh, mesh.faces[face]);
  const double norm = area.norm();
  return {norm > 0 ? Eigen::Vector3d(area / norm) : Eigen::Vector3d::Zero(), norm};
}

// The single loop that the directed edges form, or empty when they form none or several.
std::vector<int> single_loop(const std::vector<std::pair<int, int>>& edges) {
  std::map<int, int> next;
  for (const auto& [from, to] : edges)
    if (!next.emplace(from, to).second) return {};  // two edges leave one node
  std::vector<int> loop;
  int node = edges.front().first;
  do {
    loop.push_back(node);
    const auto found = next.find(node);
    if (found == next.end() || loop.size() > edges.size()) return {};
    node = found->second;
  } while (node != edges.front().first);
  return loop.size() == edges.size() ? loop : std::vector<int>{};
}

}  // namespace

int merge_coplanar_faces(PolyhedralMesh& mesh, double tolerance, const std::vector<bool>* fixed) {
  const int faces = mesh.face_count();
  std::vector<Eigen::Vector3d> normal(static_cast<std::size_t>(faces));
  std::vector<double> area(static_cast<std::size_t>(faces));
  for (int face = 0; face < faces; ++face) std::tie(normal[face], area[face]) = face_plane(mesh, face);
  // Whether every node of `face` lies within the tolerance of `reference`'s plane.
  const auto in_plane_of = [&](int face, int reference) {
    if (area[reference] == 0) return false;
    const Eigen::Vector3d origin = mesh.nodes.row(mesh.faces[reference][0]);
    return std::all_of(mesh.faces[face].begin(), mesh.faces[face].end(), [&](int node) {
      return std::abs(normal[reference].dot(Eigen::Vector3d(mesh.nodes.row(node)) - origin)) <= tolerance;
    });
  };
  // The faces between the same two cells, in either orientation: (smaller cell, larger).
  const auto cells_of = [&](int face) {
    const int first = mesh.face_cells(face, 0), second = mesh.face_cells(face, 1);
    return second < 0 ? std::pair{first, -1} : std::pair{std::min(first, second), std::max(first, second)};
  };
  const auto edge_key = [](int a, int b) { return std::pair{std::min(a, b), std::max(a, b)}; };
  std::map<std::pair<int, int>, std::vector<int>> faces_on_edge;
  for (int face = 0; face < faces; ++face) {
    const std::vector<int>& loop = mesh.faces[face];
    for (std::size_t k = 0; k < loop.size(); ++k)
      faces_on_edge[edge_key(loop[k], loop[(k + 1) % loop.size()])].push_back(face);
  }
  // Largest first: a group's plane is its first face's, and a face joins the groups of
  // its neighbours (same cells, already placed) whose planes hold it and one another.
  std::vector<int> order(static_cast<std::size_t>(faces));
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return area[a] > area[b]; });
  DisjointSets groups(faces);
  std::vector<int> plane_of(static_cast<std::size_t>(faces));
  std::iota(plane_of.begin(), plane_of.end(), 0);
  std::vector<bool> placed(static_cast<std::size_t>(faces), false);
  for (const int face : order) {
    const std::vector<int>& loop = mesh.faces[face];
    for (std::size_t k = 0; k < loop.size(); ++k)
      for (const int other : faces_on_edge[edge_key(loop[k], loop[(k + 1) % loop.size()])]) {
        if (other == face || !placed[other] || cells_of(other) != cells_of(face)) continue;
        if (fixed && ((*fixed)[face] || (*fixed)[other])) continue;
        const int mine = groups.find(face), theirs = groups.find(other);
        if (mine == theirs) continue;
        const int reference = plane_of[theirs];
        if (!in_plane_of(face, reference) || !in_plane_of(plane_of[mine], reference)) continue;
        // Not the other side of a slit (two faces of one cell at the same place, facing apart).
        const double facing =
            normal[face].dot(normal[reference]) * (mesh.face_cells(face, 0) == mesh.face_cells(reference, 0) ? 1 : -1);
        if (facing < 0) continue;
        groups.join(theirs, mine);
      }
    placed[face] = true;
  }
  std::map<int, std::vector<int>> members;
  for (int face = 0; face < faces; ++face) members[groups.find(face)].push_back(face);
  std::vector<std::vector<int>> loops;
  std::vector<std::array<int, 2>> cells;
  int merged_away = 0;
  for (const auto& [root, group] : members) {
    const int reference = plane_of[root];
    const std::array<int, 2> reference_cells{mesh.face_cells(reference, 0), mesh.face_cells(reference, 1)};
    std::vector<int> loop;
    if (group.size() > 1) {
      // The members' edges in the reference's orientation, those two members share cancelled.
      std::map<std::pair<int, int>, int> count;
      for (const int face : group) {
        const std::vector<int>& members_loop = mesh.faces[face];
        const bool reversed = mesh.face_cells(face, 0) != reference_cells[0];
        for (std::size_t k = 0; k < members_loop.size(); ++k) {
          int from = members_loop[k], to = members_loop[(k + 1) % members_loop.size()];
          if (reversed) std::swap(from, to);
          if (const auto opposite = count.find({to, from}); opposite != count.end() && opposite->second > 0)
            --opposite->second;
          else ++count[{from, to}];
        }
      }
      std::vector<std::pair<int, int>> edges;
      for (const auto& [edge, times] : count)
        for (int t = 0; t < times; ++t) edges.push_back(edge);
      if (!edges.empty()) loop = single_loop(edges);
    }
    if (loop.size() >= 3) {
      loops.push_back(std::move(loop));
      cells.push_back(reference_cells);
      merged_away += static_cast<int>(group.size()) - 1;
      continue;
    }
    for (const int face : group) {
      loops.push_back(mesh.faces[face]);
      cells.push_back({mesh.face_cells(face, 0), mesh.face_cells(face, 1)});
    }
  }
  if (merged_away == 0) return 0;
  set_faces(mesh, std::move(loops), cells);
  return merged_away;
}

int drop_straight_run_nodes(PolyhedralMesh& mesh, double tolerance, Eigen::Index first_node) {
  std::vector<std::vector<int>> faces_of(static_cast<std::size_t>(mesh.nodes.rows()));
  for (int face = 0; face < mesh.face_count(); ++face)
    for (const int node : mesh.faces[face]) faces_of[node].push_back(face);
  // Whether `node` lies between its neighbours along `loop`, within the tolerance of the
  // segment joining them.
  const auto between_neighbours = [&](const std::vector<int>& loop, int node) {
    if (loop.size() <= 3) return false;
    const std::size_t k = static_cast<std::size_t>(std::find(loop.begin(), loop.end(), node) - loop.begin());
    const Eigen::Vector3d before = mesh.nodes.row(loop[(k + loop.size() - 1) % loop.size()]),
                          after = mesh.nodes.row(loop[(k + 1) % loop.size()]), at = mesh.nodes.row(node);
    const Eigen::Vector3d segment = after - before;
    const double length_squared = segment.squaredNorm();
    if (length_squared == 0) return false;
    const double along = (at - before).dot(segment) / length_squared;
    if (!(along > 0 && along < 1 && (at - before - along * segment).norm() <= tolerance)) return false;
    // Not where the face without it would be of rounding width (a face a few ulps across,
    // all of whose nodes are "between" their neighbours).
    std::vector<int> without = loop;
    without.erase(without.begin() + static_cast<std::ptrdiff_t>(k));
    double longest = 0;
    for (std::size_t j = 0; j < without.size(); ++j)
      longest =
          std::max(longest, (mesh.nodes.row(without[j]) - mesh.nodes.row(without[(j + 1) % without.size()])).norm());
    return face_area_vector(mesh, without).norm() > tolerance * longest;
  };
  int removed = 0;
  for (std::size_t node = static_cast<std::size_t>(first_node); node < faces_of.size(); ++node) {
    const std::vector<int>& holders = faces_of[node];
    if (holders.empty() || !std::all_of(holders.begin(), holders.end(), [&](int face) {
          return between_neighbours(mesh.faces[face], static_cast<int>(node));
        }))
      continue;
    for (const int face : holders) std::erase(mesh.faces[face], static_cast<int>(node));
    ++removed;
  }
  return removed;
}

}  // namespace altfem
