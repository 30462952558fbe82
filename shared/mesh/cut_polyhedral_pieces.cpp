#include "shared/mesh/cut_polyhedral_pieces.hpp"

#include <algorithm>
#include <tuple>
#include <utility>

#include "shared/geometry/polygon_moments.hpp"
#include "shared/geometry/polyhedron_moments.hpp"
#include "shared/mesh/disjoint_sets.hpp"
#include "shared/mesh/merge_slivers.hpp"

namespace altfem {

CutPieces separate_disconnected_parts(std::vector<CutFace>& faces, const std::vector<int>& half_parent,
                                      const std::vector<int>& half_sigma, const std::vector<bool>& separates) {
  const int halves = static_cast<int>(half_parent.size());
  const auto splits = [&](int half) { return half >= 0 && separates[half]; };
  std::vector<std::tuple<int, int, int, int>> holders;  // (half, edge's lower node, upper node, face side)
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (const int s : {0, 1}) {
      const int half = s == 0 ? faces[f].first : faces[f].second;
      if (!splits(half)) continue;
      const std::vector<int>& loop = faces[f].loop;
      for (std::size_t k = 0; k < loop.size(); ++k) {
        const auto [lower, upper] = std::minmax(loop[k], loop[(k + 1) % loop.size()]);
        holders.emplace_back(half, lower, upper, static_cast<int>(2 * f) + s);
      }
    }
  std::sort(holders.begin(), holders.end());
  DisjointSets parts(static_cast<int>(2 * faces.size()));
  for (std::size_t k = 1; k < holders.size(); ++k)
    if (std::get<0>(holders[k]) == std::get<0>(holders[k - 1]) &&
        std::get<1>(holders[k]) == std::get<1>(holders[k - 1]) &&
        std::get<2>(holders[k]) == std::get<2>(holders[k - 1]))
      parts.join(std::get<3>(holders[k - 1]), std::get<3>(holders[k]));
  // Per half, its parts' roots in the order their faces come.
  std::vector<std::vector<int>> roots(halves);
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (const int s : {0, 1}) {
      const int half = s == 0 ? faces[f].first : faces[f].second;
      if (!splits(half)) continue;
      const int root = parts.find(static_cast<int>(2 * f) + s);
      if (std::find(roots[half].begin(), roots[half].end(), root) == roots[half].end()) roots[half].push_back(root);
    }
  std::vector<int> first_part(halves + 1, 0);
  CutPieces pieces;
  for (int half = 0; half < halves; ++half) {
    const int count = splits(half) ? static_cast<int>(roots[half].size()) : 1;
    first_part[half + 1] = first_part[half] + count;
    for (int part = 0; part < count; ++part) {
      pieces.parent.push_back(half_parent[half]);
      pieces.sigma.push_back(half_sigma[half]);
    }
  }
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (const int s : {0, 1}) {
      int& half = s == 0 ? faces[f].first : faces[f].second;
      if (half < 0) continue;
      int part = 0;
      if (splits(half)) {
        const int root = parts.find(static_cast<int>(2 * f) + s);
        part = static_cast<int>(std::find(roots[half].begin(), roots[half].end(), root) - roots[half].begin());
      }
      half = first_part[half] + part;
    }
  return pieces;
}

int duplicate_separated_nodes(std::vector<CutFace>& faces, const std::vector<bool>& opened_node,
                              const std::vector<int>& piece_sigma, std::vector<Eigen::Vector3d>& nodes,
                              std::vector<NodeSource>& sources) {
  std::vector<std::pair<int, int>> holders;  // (node, face)
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (const int node : faces[f].loop)
      if (opened_node[node]) holders.emplace_back(node, static_cast<int>(f));
  std::sort(holders.begin(), holders.end());
  int duplicated = 0;
  std::vector<int> pieces, roots, copy_of_root;
  for (std::size_t begin = 0; begin < holders.size();) {
    const int node = holders[begin].first;
    std::size_t end = begin;
    while (end < holders.size() && holders[end].first == node) ++end;
    pieces.clear();
    for (std::size_t k = begin; k < end; ++k) {
      const CutFace& face = faces[holders[k].second];
      pieces.push_back(face.first);
      if (face.second >= 0) pieces.push_back(face.second);
    }
    std::sort(pieces.begin(), pieces.end());
    pieces.erase(std::unique(pieces.begin(), pieces.end()), pieces.end());
    const auto local = [&](int piece_index) {
      return static_cast<int>(std::lower_bound(pieces.begin(), pieces.end(), piece_index) - pieces.begin());
    };
    DisjointSets groups(static_cast<int>(pieces.size()));
    for (std::size_t k = begin; k < end; ++k) {
      const CutFace& face = faces[holders[k].second];
      if (face.second >= 0) groups.join(local(face.first), local(face.second));
    }
    roots.clear();
    for (int i = 0; i < static_cast<int>(pieces.size()); ++i)
      if (std::find(roots.begin(), roots.end(), groups.find(i)) == roots.end()) roots.push_back(groups.find(i));
    const auto kept = std::find_if(roots.begin(), roots.end(), [&](int root) {
      for (int i = 0; i < static_cast<int>(pieces.size()); ++i)
        if (groups.find(i) == root && piece_sigma[pieces[i]] > 0) return true;
      return false;
    });
    if (kept != roots.end()) std::rotate(roots.begin(), kept, kept + 1);
    copy_of_root.assign(pieces.size(), node);
    for (std::size_t r = 1; r < roots.size(); ++r) {
      copy_of_root[roots[r]] = static_cast<int>(nodes.size());
      nodes.push_back(nodes[node]);
      sources.push_back(sources[node]);
      ++duplicated;
    }
    for (std::size_t k = begin; k < end; ++k) {
      CutFace& face = faces[holders[k].second];
      const int copy = copy_of_root[groups.find(local(face.first))];
      if (copy != node) std::replace(face.loop.begin(), face.loop.end(), node, copy);
    }
    begin = end;
  }
  return duplicated;
}

int merge_pieces_without_volume(PolyhedralMesh& mesh, std::vector<int>& parent, std::vector<NodeSource>& sources,
                                const std::vector<bool>& is_piece) {
  const int cells = mesh.cell_count();
  DisjointSets groups(cells);
  int merged = 0;
  for (int cell = 0; cell < cells; ++cell) {
    if (!is_piece[cell] || polyhedron_moments(cell_polyhedron(mesh, cell), 0)(0) > 0) continue;
    int neighbour = -1;
    double largest = 0;
    for (const int face : mesh.cell_faces[cell]) {
      const int other = mesh.face_cells(face, 0) == cell ? mesh.face_cells(face, 1) : mesh.face_cells(face, 0);
      if (other < 0) continue;
      Eigen::MatrixXd polygon(static_cast<Eigen::Index>(mesh.faces[face].size()), 3);
      for (std::size_t k = 0; k < mesh.faces[face].size(); ++k)
        polygon.row(static_cast<Eigen::Index>(k)) = mesh.nodes.row(mesh.faces[face][k]);
      const double area = polygon_area_vector(polygon).norm();
      if (neighbour < 0 || area > largest) std::tie(neighbour, largest) = std::pair{other, area};
    }
    if (neighbour < 0 || groups.find(neighbour) == groups.find(cell)) continue;
    groups.join(neighbour, cell);
    ++merged;
  }
  if (merged == 0) return 0;
  std::vector<int> new_cell;
  const std::vector<int> kept_nodes = merge_cell_groups(mesh, groups, PolyhedralCellKind::merged, &new_cell);
  std::vector<int> merged_parent(static_cast<std::size_t>(mesh.cell_count()));
  for (int cell = 0; cell < cells; ++cell)
    if (groups.find(cell) == cell) merged_parent[new_cell[cell]] = parent[cell];
  parent = std::move(merged_parent);
  std::vector<NodeSource> kept_sources;
  for (const int node : kept_nodes) kept_sources.push_back(sources[node]);
  sources = std::move(kept_sources);
  return merged;
}

}  // namespace altfem
