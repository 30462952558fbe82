#include "shared/mesh/cut_tetrahedral_mesh.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "shared/geometry/exact_orientation.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"

namespace altfem {
namespace {

// The piece's node loops, each counter-clockwise seen from outside the piece.
std::vector<std::vector<int>> outward_loops(const PolyhedralMesh& mesh, int cell) {
  std::vector<std::vector<int>> loops;
  for (const int face : mesh.cell_faces[cell]) {
    std::vector<int> loop = mesh.faces[face];
    if (mesh.face_cells(face, 0) != cell) std::reverse(loop.begin(), loop.end());
    loops.push_back(std::move(loop));
  }
  return loops;
}

// Below this fraction of its longest edge cubed, a tetrahedron is a sliver whose pieces'
// rounded volumes may have either sign (a blade nearly parallel to a face leaves such
// slivers): it is left out, losing no more volume than that, so that every kept one and
// its pieces have positive volumes in floating point too and can be cut again.
constexpr double flat_fraction = 1e-14;

// Flat: not positively oriented (exact predicate) or a sliver by its rounded volume.
bool is_flat(const Eigen::MatrixXd& nodes, const std::array<int, 4>& row) {
  const Eigen::Vector3d origin = nodes.row(row[0]), a = nodes.row(row[1]), b = nodes.row(row[2]), c = nodes.row(row[3]);
  if (orientation_sign(a, b, c, origin) >= 0) return true;
  const double longest = std::max(
      {(a - origin).norm(), (b - origin).norm(), (c - origin).norm(), (b - a).norm(), (c - a).norm(), (c - b).norm()});
  return (a - origin).cross(b - origin).dot(c - origin) / 6 <= flat_fraction * longest * longest * longest;
}

// The input without its flat tetrahedra (an earlier cut's slivers), with each kept
// row's index in the input.
VolumeMesh without_flat_tetrahedra(const VolumeMesh& mesh, std::vector<int>& kept, int& flat) {
  VolumeMesh result{ElementType::tet4, mesh.nodes, Eigen::MatrixXi(mesh.cells.rows(), 4)};
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell) {
    const std::array<int, 4> row{mesh.cells(cell, 0), mesh.cells(cell, 1), mesh.cells(cell, 2), mesh.cells(cell, 3)};
    if (is_flat(mesh.nodes, row)) {
      ++flat;
      continue;
    }
    result.cells.row(static_cast<Eigen::Index>(kept.size())) = mesh.cells.row(cell);
    kept.push_back(static_cast<int>(cell));
  }
  result.cells.conservativeResize(static_cast<Eigen::Index>(kept.size()), 4);
  return result;
}

}  // namespace

TetrahedralCut cut_tetrahedral_mesh(const VolumeMesh& mesh, const CuttingPlane& plane) {
  if (mesh.element_type != ElementType::tet4)
    throw std::invalid_argument("cut_tetrahedral_mesh: the mesh must be of Tet4 cells");
  TetrahedralCut result;
  std::vector<int> kept_cell;
  const VolumeMesh input = without_flat_tetrahedra(mesh, kept_cell, result.flat_tetrahedra);
  // polyhedral_mesh_from_volume_mesh keeps the used nodes in their order.
  std::vector<int> input_node;
  {
    std::vector<bool> used(static_cast<std::size_t>(mesh.nodes.rows()), false);
    for (Eigen::Index cell = 0; cell < input.cells.rows(); ++cell)
      for (int corner = 0; corner < 4; ++corner) used[input.cells(cell, corner)] = true;
    for (std::size_t node = 0; node < used.size(); ++node)
      if (used[node]) input_node.push_back(static_cast<int>(node));
  }
  const PolyhedralCut cut = cut_polyhedral_mesh(polyhedral_mesh_from_volume_mesh(input), plane, false);
  const PolyhedralMesh& pieces = cut.mesh;

  result.crossed_tetrahedra = cut.crossed_cells;
  result.joined_tetrahedra = cut.joined_cells;
  result.separated_faces = cut.separated_faces;
  result.duplicated_nodes = cut.duplicated_nodes;
  result.snapped_nodes = cut.snapped_nodes;
  result.mesh.element_type = ElementType::tet4;
  result.mesh.nodes = pieces.nodes;
  for (const NodeSource& source : cut.node_sources)
    result.node_sources.push_back({input_node[source.first], input_node[source.second], source.weight});

  // Input node → the cut node of the same input node used by one piece (its copy on the
  // piece's side when it lies on the blade).
  std::vector<std::array<int, 4>> rows;
  rows.reserve(static_cast<std::size_t>(input.cells.rows()) + 2 * static_cast<std::size_t>(cut.crossed_cells));
  for (int piece = 0; piece < pieces.cell_count(); ++piece) {
    const int parent = kept_cell[cut.parent_cell[piece]];
    const std::vector<std::vector<int>> loops = outward_loops(pieces, piece);
    if (pieces.cell_kinds[piece] != PolyhedralCellKind::split) {
      // Not crossed: the input row, each corner as the copy this piece holds.
      std::array<int, 4> row{};
      for (int corner = 0; corner < 4; ++corner)
        for (const auto& loop : loops)
          for (const int node : loop)
            if (result.node_sources[node].weight == 0 && result.node_sources[node].first == mesh.cells(parent, corner))
              row[corner] = node;
      rows.push_back(row);
      result.parent_tetrahedron.push_back(parent);
      continue;
    }
    int apex = loops[0][0];
    for (const auto& loop : loops) apex = std::min(apex, *std::min_element(loop.begin(), loop.end()));
    for (std::vector<int> loop : loops) {
      if (std::find(loop.begin(), loop.end(), apex) != loop.end()) continue;
      std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
      for (std::size_t k = 1; k + 1 < loop.size(); ++k) {
        const std::array<int, 4> row{apex, loop[0], loop[k], loop[k + 1]};
        if (is_flat(pieces.nodes, row)) {
          ++result.flat_tetrahedra;
          continue;
        }
        rows.push_back(row);
        result.parent_tetrahedron.push_back(parent);
      }
    }
  }
  result.mesh.cells.resize(static_cast<Eigen::Index>(rows.size()), 4);
  for (std::size_t row = 0; row < rows.size(); ++row)
    for (int corner = 0; corner < 4; ++corner)
      result.mesh.cells(static_cast<Eigen::Index>(row), corner) = rows[row][corner];
  return result;
}

}  // namespace altfem
