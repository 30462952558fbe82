#include "shared/mesh/merge_slivers.hpp"

#include <algorithm>
#include <numeric>

#include "shared/mesh/disjoint_sets.hpp"

namespace altfem {

std::vector<int> merge_cell_groups(PolyhedralMesh& mesh, DisjointSets& groups, PolyhedralCellKind grouped_kind,
                                   std::vector<int>* new_cell_of) {
  const int cell_count = mesh.cell_count();
  std::vector<int> new_cell(cell_count, -1), group_size(cell_count, 0);
  int new_count = 0;
  for (int cell = 0; cell < cell_count; ++cell) ++group_size[groups.find(cell)];
  std::vector<PolyhedralCellKind> kinds;
  for (int cell = 0; cell < cell_count; ++cell) {
    const int root = groups.find(cell);
    if (new_cell[root] < 0) {
      new_cell[root] = new_count++;
      kinds.push_back(group_size[root] > 1 ? grouped_kind : mesh.cell_kinds[root]);
    }
    new_cell[cell] = new_cell[root];
  }
  if (new_cell_of) *new_cell_of = new_cell;
  std::vector<std::vector<int>> faces;
  std::vector<std::array<int, 2>> face_cells;
  for (int face = 0; face < mesh.face_count(); ++face) {
    const int owner = new_cell[mesh.face_cells(face, 0)];
    const int neighbour = mesh.face_cells(face, 1) < 0 ? -1 : new_cell[mesh.face_cells(face, 1)];
    if (owner == neighbour) continue;
    faces.push_back(mesh.faces[face]);
    face_cells.push_back({owner, neighbour});
  }
  mesh.cell_kinds = std::move(kinds);
  mesh.cell_faces.assign(new_count, {});
  set_faces(mesh, std::move(faces), face_cells);
  return drop_unused_nodes(mesh);
}

std::vector<int> drop_unused_nodes(PolyhedralMesh& mesh) {
  std::vector<bool> used(mesh.nodes.rows(), false);
  for (const auto& loop : mesh.faces)
    for (const int node : loop) used[node] = true;
  std::vector<int> node_map(mesh.nodes.rows(), -1), kept;
  for (Eigen::Index node = 0; node < mesh.nodes.rows(); ++node)
    if (used[node]) {
      node_map[node] = static_cast<int>(kept.size());
      kept.push_back(static_cast<int>(node));
    }
  for (auto& loop : mesh.faces)
    for (int& node : loop) node = node_map[node];
  Eigen::MatrixXd nodes(static_cast<Eigen::Index>(kept.size()), 3);
  for (std::size_t node = 0; node < kept.size(); ++node)
    nodes.row(static_cast<Eigen::Index>(node)) = mesh.nodes.row(kept[node]);
  mesh.nodes = std::move(nodes);
  return kept;
}

int merge_slivers(PolyhedralMesh& mesh, double minimum_volume) {
  std::vector<double> thresholds(static_cast<std::size_t>(mesh.cell_count()), 0.0);
  for (int cell = 0; cell < mesh.cell_count(); ++cell)
    if (mesh.cell_kinds[cell] == PolyhedralCellKind::cut) thresholds[cell] = minimum_volume;
  return merge_small_pieces(mesh, thresholds).merged;
}

MergedPieces merge_small_pieces(PolyhedralMesh& mesh, const std::vector<double>& minimum_volume) {
  const int cell_count = mesh.cell_count();
  std::vector<int> slivers;
  for (int cell = 0; cell < cell_count; ++cell)
    if (mesh.cell_volumes(cell) < minimum_volume[cell]) slivers.push_back(cell);
  MergedPieces result;
  if (slivers.empty()) return result;
  std::sort(slivers.begin(), slivers.end(), [&](int a, int b) { return mesh.cell_volumes(a) < mesh.cell_volumes(b); });

  DisjointSets groups(cell_count);
  std::vector<double> group_volume(mesh.cell_volumes.data(), mesh.cell_volumes.data() + cell_count);
  std::vector<std::vector<int>> members(cell_count);
  for (int cell = 0; cell < cell_count; ++cell) members[cell] = {cell};
  int merged = 0;
  for (int sliver : slivers) {
    const int root = groups.find(sliver);
    if (group_volume[root] >= minimum_volume[sliver]) continue;  // already grown by earlier merges
    // The neighbouring group across the largest face of any cell of this group.
    int best_face = -1;
    for (int member : members[root])
      for (int face : mesh.cell_faces[member]) {
        const int other = mesh.face_cells(face, 0) == member ? mesh.face_cells(face, 1) : mesh.face_cells(face, 0);
        if (other < 0 || groups.find(other) == root) continue;
        if (best_face < 0 || mesh.face_areas(face) > mesh.face_areas(best_face)) best_face = face;
      }
    if (best_face < 0) continue;  // a separate bit of the object: kept
    const int owner = groups.find(mesh.face_cells(best_face, 0));
    const int target = owner == root ? groups.find(mesh.face_cells(best_face, 1)) : owner;
    groups.join(target, root);
    group_volume[target] += group_volume[root];
    members[target].insert(members[target].end(), members[root].begin(), members[root].end());
    members[root].clear();
    ++merged;
  }
  result.merged = merged;
  if (merged > 0) {
    result.kept_nodes = merge_cell_groups(mesh, groups, PolyhedralCellKind::merged, &result.new_cell);
    compute_polyhedral_geometry(mesh);
  }
  return result;
}

}  // namespace altfem
