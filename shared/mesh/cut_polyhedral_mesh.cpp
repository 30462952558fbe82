#include "shared/mesh/cut_polyhedral_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "shared/mesh/cut_by_surface.hpp"
#include "shared/mesh/cut_polyhedral_builder.hpp"
#include "shared/mesh/disjoint_sets.hpp"

namespace altfem {
namespace polyhedral_cut {

bool CutBuilder::covers_section(int cell) {
  if (blade_.whole_plane()) return true;
  for (const int face : mesh_.cell_faces[cell]) {
    const std::vector<int>& loop = mesh_.faces[face];
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const int u = loop[k], v = loop[(k + 1) % loop.size()];
      if (side_[u] == 0 && !blade_.covers(nodes_[u])) return false;
      if (side_[u] * side_[v] >= 0) continue;
      const auto key = std::minmax(u, v);
      auto found = crossing_covered_.find(key);
      if (found == crossing_covered_.end())
        found = crossing_covered_.emplace(key, blade_.covers_crossing(nodes_[key.first], nodes_[key.second])).first;
      if (!found->second) return false;
    }
  }
  return true;
}

std::vector<bool> CutBuilder::cells_of_piece_at() const {
  const int cells = mesh_.cell_count();
  if (!piece_at_) return std::vector<bool>(cells, true);
  DisjointSets pieces(cells);
  int nearest = -1;
  double nearest_distance = 0;
  for (int face = 0; face < mesh_.face_count(); ++face) {
    if (mesh_.face_cells(face, 1) >= 0) pieces.join(mesh_.face_cells(face, 0), mesh_.face_cells(face, 1));
    for (const int node : mesh_.faces[face]) {
      const double distance = (nodes_[node] - *piece_at_).squaredNorm();
      if (nearest < 0 || distance < nearest_distance) std::tie(nearest, nearest_distance) = std::pair{node, distance};
    }
  }
  std::vector<bool> holds(cells, false), result(cells, false);
  for (int face = 0; face < mesh_.face_count(); ++face)
    if (std::find(mesh_.faces[face].begin(), mesh_.faces[face].end(), nearest) != mesh_.faces[face].end())
      for (const int side : {mesh_.face_cells(face, 0), mesh_.face_cells(face, 1)})
        if (side >= 0) holds[pieces.find(side)] = true;
  for (int cell = 0; cell < cells; ++cell) result[cell] = holds[pieces.find(cell)];
  return result;
}

void CutBuilder::classify_cells() {
  const int cells = mesh_.cell_count();
  crossed_.assign(cells, false);
  cap_covered_.assign(cells, false);
  cell_sigma_.assign(cells, +1);
  convex_.assign(cells, true);
  first_piece_.resize(cells);
  std::vector<bool> reached(cells, false);
  DisjointSets joined(cells);
  in_piece_ = cells_of_piece_at();
  for (int cell = 0; cell < cells; ++cell) {
    // Through its faces' loops, a node once per face it is on: every step classifies
    // every cell, and a set of its nodes each time was most of a surface blade's cut.
    bool positive = false, negative = false;
    for (const int face : mesh_.cell_faces[cell])
      for (const int node : mesh_.faces[face]) {
        positive |= side_[node] > 0;
        negative |= side_[node] < 0;
      }
    reached[cell] = positive && negative && in_piece_[cell] && scope_.action != CutAction::separate;
    cell_sigma_[cell] = negative && !positive ? -1 : +1;
    if (reached[cell] && scope_.action == CutAction::cut) cap_covered_[cell] = covers_section(cell);
    // A split step's region is where it starts: it spreads to every cell joined to one
    // there through faces the plane crosses with `spread`, else it splits only those.
    if (reached[cell] && scope_.action == CutAction::split) {
      const bool starts_here = in_scope(cell) && (whole_.empty() || !whole_[cell]);
      cap_covered_[cell] = scope_.spread && starts_here;
      reached[cell] = scope_.spread || starts_here;
    }
  }
  touched_.assign(cells, false);
  for (int face = 0; face < mesh_.face_count(); ++face)
    if (mesh_.face_cells(face, 1) >= 0 && has_both_sides(mesh_.faces[face]))
      joined.join(mesh_.face_cells(face, 0), mesh_.face_cells(face, 1));
  std::vector<bool> covered_group(cells, false);
  for (int cell = 0; cell < cells; ++cell)
    if (cap_covered_[cell]) covered_group[joined.find(cell)] = true;
  // A spreading split keeps whole every cell joined to one it must keep whole.
  if (!whole_.empty() && scope_.spread)
    for (int cell = 0; cell < cells; ++cell)
      if (whole_[cell]) covered_group[joined.find(cell)] = false;
  for (int cell = 0; cell < cells; ++cell) {
    first_piece_[cell] = static_cast<int>(parent_.size());
    parent_.push_back(cell);
    // A split step that does not spread splits every cell it reaches
    // (add_crossings_to_whole_faces keeps the mesh conforming), its pieces joined.
    crossed_[cell] =
        reached[cell] && ((scope_.action == CutAction::split && !scope_.spread) || covered_group[joined.find(cell)]);
    if (!crossed_[cell]) continue;
    convex_[cell] = is_convex_cell(mesh_, cell, nodes_of(cell));
    parent_.push_back(cell);
    ++crossed_count_;
    if (scope_.action == CutAction::split) cap_covered_[cell] = false;  // its pieces stay joined
    if (!cap_covered_[cell]) ++joined_count_;
  }
  cap_edges_.resize(parent_.size());
}

int CutBuilder::crossing_node(int u, int v) {
  const auto key = std::minmax(u, v);
  const auto found = crossings_.find(key);
  if (found != crossings_.end()) return found->second;
  const Eigen::Vector3d& p = nodes_[key.first];
  const Eigen::Vector3d& q = nodes_[key.second];
  const double dp = (p - blade_.a).dot(blade_.normal), dq = (q - blade_.a).dot(blade_.normal);
  // The sides were decided exactly; these rounded distances only place the node (and
  // may round to 0 for a node a hair off the blade).
  const double t = dp != dq ? std::clamp(dp / (dp - dq), 0.0, 1.0) : 0.5;
  nodes_.push_back(p + t * (q - p));
  sources_.push_back({key.first, key.second, t});
  side_.push_back(0);
  const int node = static_cast<int>(nodes_.size()) - 1;
  crossings_.emplace(key, node);
  return node;
}

}  // namespace polyhedral_cut

PolyhedralCut cut_polyhedral_mesh(const PolyhedralMesh& mesh, const CuttingPlane& plane, bool compute_geometry,
                                  const CutScope& scope) {
  if (plane.surface) return cut_polyhedral_mesh_by_surface(mesh, *plane.surface, compute_geometry);
  if (scope.action != CutAction::split) return polyhedral_cut::CutBuilder(mesh, plane, compute_geometry, scope).build();
  std::vector<bool> whole(static_cast<std::size_t>(mesh.cell_count()), false);
  for (;;) {
    try {
      return polyhedral_cut::CutBuilder(mesh, plane, compute_geometry, scope, whole).build();
    } catch (const polyhedral_cut::UnsplittableFace& face) {
      for (const int cell : face.cells)
        if (cell >= 0) {
          if (whole[cell]) throw;
          whole[cell] = true;
        }
    }
  }
}

}  // namespace altfem
