#pragma once
// The pieces of a tetrahedral mesh, joined through the faces two tetrahedra share: the
// cut-tetrahedra tests read conformity from them (a face only one tetrahedron holds is
// boundary, so a face left unmatched inside adds to the boundary's area).
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <map>
#include <utility>
#include <vector>

#include "shared/mesh/disjoint_sets.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem::test {

inline double tetrahedron_volume(const Eigen::MatrixXd& nodes, const Eigen::MatrixXi& cells, Eigen::Index cell) {
  const Eigen::Vector3d a = nodes.row(cells(cell, 0)), b = nodes.row(cells(cell, 1)), c = nodes.row(cells(cell, 2)),
                        d = nodes.row(cells(cell, 3));
  return (b - a).cross(c - a).dot(d - a) / 6;
}

// The tetrahedra's pieces (joined through shared faces; with `group`, per tetrahedron,
// only those of one group) by volume, smallest first, the area of the faces only one
// tetrahedron holds, and per group its number of pieces.
struct TetrahedralPieces {
  std::vector<double> volumes;
  double boundary_area = 0;
  std::map<int, int> pieces_of_group;
};

inline TetrahedralPieces tetrahedral_pieces(const VolumeMesh& mesh, const std::vector<int>& group = {}) {
  // Every tetrahedron's four faces (sorted corners) with their holder, sorted: a face two
  // tetrahedra hold comes twice in a row.
  std::vector<std::pair<std::array<int, 3>, int>> holders;
  holders.reserve(4 * static_cast<std::size_t>(mesh.cells.rows()));
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell)
    for (int skipped = 0; skipped < 4; ++skipped) {
      std::array<int, 3> face;
      for (int k = 0, j = 0; k < 4; ++k)
        if (k != skipped) face[j++] = mesh.cells(cell, k);
      std::sort(face.begin(), face.end());
      holders.emplace_back(face, static_cast<int>(cell));
    }
  std::sort(holders.begin(), holders.end());
  DisjointSets pieces(static_cast<int>(mesh.cells.rows()));
  TetrahedralPieces result;
  for (std::size_t first = 0, last = 0; first < holders.size(); first = last) {
    while (last < holders.size() && holders[last].first == holders[first].first) ++last;
    const int one = holders[first].second, other = last - first == 2 ? holders[first + 1].second : -1;
    if (other >= 0 && (group.empty() || group[one] == group[other])) pieces.join(pieces.find(one), pieces.find(other));
    if (last - first != 1) continue;
    const std::array<int, 3>& face = holders[first].first;
    const Eigen::Vector3d a = mesh.nodes.row(face[0]), b = mesh.nodes.row(face[1]), c = mesh.nodes.row(face[2]);
    result.boundary_area += (b - a).cross(c - a).norm() / 2;
  }
  std::map<int, double> volume_of;
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell)
    volume_of[pieces.find(static_cast<int>(cell))] += tetrahedron_volume(mesh.nodes, mesh.cells, cell);
  for (const auto& [root, volume] : volume_of) {
    result.volumes.push_back(volume);
    ++result.pieces_of_group[group.empty() ? 0 : group[root]];
  }
  std::sort(result.volumes.begin(), result.volumes.end());
  return result;
}

}  // namespace altfem::test
