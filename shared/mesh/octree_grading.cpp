#include "shared/mesh/octree_grading.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cstring>
#include <map>
#include <unordered_map>
#include <unordered_set>

#include "shared/common/error.hpp"
#include "shared/mesh/merge_slivers.hpp"

namespace altfem {

namespace {

/// Counts of hexahedron-filled grid cells in boxes, by a summed-volume table.
class FilledCellCounts {
public:
  FilledCellCounts(const Eigen::Vector3i& cells, const std::vector<int>& grid_hexahedra)
      : cells_(cells), sums_(static_cast<std::size_t>((cells.array() + 1).prod()), 0) {
    for (int k = 0; k < cells(2); ++k)
      for (int j = 0; j < cells(1); ++j)
        for (int i = 0; i < cells(0); ++i) {
          const int filled = grid_hexahedra[i + cells(0) * (j + cells(1) * k)] >= 0;
          at(i + 1, j + 1, k + 1) = filled + at(i, j + 1, k + 1) + at(i + 1, j, k + 1) + at(i + 1, j + 1, k) -
                                    at(i, j, k + 1) - at(i, j + 1, k) - at(i + 1, j, k) + at(i, j, k);
        }
  }
  /// Whether every cell of [low, high) is inside the grid and filled.
  bool all_filled(const Eigen::Vector3i& low, const Eigen::Vector3i& high) const {
    if ((low.array() < 0).any() || (high.array() > cells_.array()).any()) return false;
    const long long count = at(high(0), high(1), high(2)) - at(low(0), high(1), high(2)) -
                            at(high(0), low(1), high(2)) - at(high(0), high(1), low(2)) + at(low(0), low(1), high(2)) +
                            at(low(0), high(1), low(2)) + at(high(0), low(1), low(2)) - at(low(0), low(1), low(2));
    return count == static_cast<long long>((high - low).prod());
  }

private:
  long long& at(int i, int j, int k) {
    return sums_[i + (cells_(0) + 1) * (j + (cells_(1) + 1) * static_cast<std::size_t>(k))];
  }
  long long at(int i, int j, int k) const {
    return sums_[i + (cells_(0) + 1) * (j + (cells_(1) + 1) * static_cast<std::size_t>(k))];
  }
  Eigen::Vector3i cells_;
  std::vector<long long> sums_;
};

/// The axis of a face lying in a plane x_axis = const, or −1.
int face_axis(const PolyhedralMesh& mesh, int face) {
  const auto& loop = mesh.faces[face];
  for (int axis = 0; axis < 3; ++axis)
    if (std::all_of(loop.begin(), loop.end(),
                    [&](int node) { return mesh.nodes(node, axis) == mesh.nodes(loop[0], axis); }))
      return axis;
  return -1;
}

/// One loop, outward from `owner`, from the directed edges left after opposite pairs
/// cancel: the outline of coplanar faces of one cell pair (a rectangle of grid faces).
std::vector<int> outline(const PolyhedralMesh& mesh, const std::vector<int>& faces, int owner) {
  std::map<std::pair<int, int>, int> edges;
  for (int face : faces) {
    std::vector<int> loop = mesh.faces[face];
    if (mesh.face_cells(face, 0) != owner) std::reverse(loop.begin(), loop.end());  // outward from `owner`
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const int a = loop[i], b = loop[(i + 1) % loop.size()];
      const auto reverse = edges.find({b, a});
      if (reverse != edges.end()) {
        edges.erase(reverse);
      } else {
        ++edges[{a, b}];
      }
    }
  }
  std::unordered_map<int, int> next;
  for (const auto& [edge, count] : edges) next[edge.first] = edge.second;
  std::vector<int> loop{edges.begin()->first.first};
  while (true) {
    const int following = next.at(loop.back());
    if (following == loop.front()) break;
    loop.push_back(following);
  }
  if (loop.size() != edges.size())
    throw NumericalError("octree grading: coplanar faces of one cell pair do not form one polygon");
  return loop;
}

bool straight_at(const PolyhedralMesh& mesh, const std::vector<int>& loop, std::size_t i) {
  const Eigen::Vector3d previous = mesh.nodes.row(loop[(i + loop.size() - 1) % loop.size()]);
  const Eigen::Vector3d here = mesh.nodes.row(loop[i]);
  const Eigen::Vector3d next = mesh.nodes.row(loop[(i + 1) % loop.size()]);
  return (here - previous).cross(next - here).isZero(0.0);  // grid nodes: exact for axis-aligned edges
}

/// Joins coplanar faces between the same two cells (one of them coarse) into one polygon and
/// drops the nodes that are then on a straight edge of every face using them.
void join_coplanar_faces(PolyhedralMesh& mesh) {
  std::map<std::array<long long, 4>, std::vector<int>> groups;  // (owner, neighbour, axis, plane bits)
  for (int face = 0; face < mesh.face_count(); ++face) {
    const int owner = mesh.face_cells(face, 0), neighbour = mesh.face_cells(face, 1);
    // Coarse cells lie inside filled hexahedra, so their faces are interior.
    const bool coarse = neighbour >= 0 && (mesh.cell_kinds[owner] == PolyhedralCellKind::coarse ||
                                           mesh.cell_kinds[neighbour] == PolyhedralCellKind::coarse);
    const int axis = face_axis(mesh, face);
    if (!coarse || axis < 0) continue;
    const double plane = mesh.nodes(mesh.faces[face][0], axis);
    long long plane_bits;
    std::memcpy(&plane_bits, &plane, sizeof plane);
    groups[{std::min(owner, neighbour), std::max(owner, neighbour), axis, plane_bits}].push_back(face);
  }
  std::vector<bool> removed(mesh.face_count(), false);
  std::unordered_set<int> outline_nodes;
  std::vector<std::vector<int>> joined_faces;
  std::vector<std::array<int, 2>> joined_cells;
  for (const auto& [key, faces] : groups) {
    if (faces.size() < 2) continue;
    joined_faces.push_back(outline(mesh, faces, static_cast<int>(key[0])));
    joined_cells.push_back({static_cast<int>(key[0]), static_cast<int>(key[1])});
    for (int face : faces) removed[face] = true;
    outline_nodes.insert(joined_faces.back().begin(), joined_faces.back().end());
  }
  std::vector<std::vector<int>> faces;
  std::vector<std::array<int, 2>> face_cells;
  for (int face = 0; face < mesh.face_count(); ++face)
    if (!removed[face]) {
      faces.push_back(std::move(mesh.faces[face]));
      face_cells.push_back({mesh.face_cells(face, 0), mesh.face_cells(face, 1)});
    }
  faces.insert(faces.end(), joined_faces.begin(), joined_faces.end());
  face_cells.insert(face_cells.end(), joined_cells.begin(), joined_cells.end());

  // A node of a joined outline stays where some face turns at it (a corner, or a finer
  // neighbour's node on a coarse edge: Martin et al. 2008, Fig. 4).
  std::unordered_set<int> corners;
  for (const auto& loop : faces)
    for (std::size_t i = 0; i < loop.size(); ++i)
      if (outline_nodes.count(loop[i]) && !straight_at(mesh, loop, i)) corners.insert(loop[i]);
  for (auto& loop : faces)
    loop.erase(std::remove_if(loop.begin(), loop.end(),
                              [&](int node) { return outline_nodes.count(node) && !corners.count(node); }),
               loop.end());

  set_faces(mesh, std::move(faces), face_cells);
}

}  // namespace

int grade_interior_hexahedra(PolyhedralMesh& mesh, const Eigen::Vector3i& grid_cells,
                             const std::vector<int>& grid_hexahedra, int max_level) {
  const FilledCellCounts counts(grid_cells, grid_hexahedra);
  std::vector<bool> assigned(grid_hexahedra.size(), false);
  DisjointSets groups(mesh.cell_count());
  int coarse_cells = 0;
  for (int level = max_level; level >= 1; --level) {
    const int size = 1 << level;
    const Eigen::Vector3i blocks = grid_cells / size;
    for (int k = 0; k < blocks(2); ++k)
      for (int j = 0; j < blocks(1); ++j)
        for (int i = 0; i < blocks(0); ++i) {
          const Eigen::Vector3i low = Eigen::Vector3i(i, j, k) * size, high = low.array() + size;
          const int first = low(0) + grid_cells(0) * (low(1) + grid_cells(1) * low(2));
          if (assigned[first]) continue;  // inside a larger block already
          // 2:1 balance: the block and twice its size around it are filled hexahedra.
          if (!counts.all_filled(low.array() - 2 * size, high.array() + 2 * size)) continue;
          ++coarse_cells;
          for (int z = low(2); z < high(2); ++z)
            for (int y = low(1); y < high(1); ++y)
              for (int x = low(0); x < high(0); ++x) {
                const int cell = x + grid_cells(0) * (y + grid_cells(1) * z);
                assigned[cell] = true;
                groups.join(grid_hexahedra[first], grid_hexahedra[cell]);
              }
        }
  }
  if (coarse_cells == 0) return 0;
  merge_cell_groups(mesh, groups, PolyhedralCellKind::coarse);
  join_coplanar_faces(mesh);
  drop_unused_nodes(mesh);
  return coarse_cells;
}

}  // namespace altfem
