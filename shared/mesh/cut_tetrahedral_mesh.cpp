#include "shared/mesh/cut_tetrahedral_mesh.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <utility>

#include "shared/common/error.hpp"
#include "shared/geometry/exact_orientation.hpp"
#include "shared/mesh/cone_tetrahedra.hpp"
#include "shared/mesh/cut_tetrahedral_parts.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"

namespace altfem {
namespace tetrahedral_cut {

TetrahedronRow row_of(const VolumeMesh& mesh, int cell) {
  return {mesh.cells(cell, 0), mesh.cells(cell, 1), mesh.cells(cell, 2), mesh.cells(cell, 3)};
}

VolumeMesh tetrahedra_of_rows(const Eigen::MatrixXd& nodes, const std::vector<TetrahedronRow>& rows) {
  VolumeMesh mesh{ElementType::tet4, nodes, Eigen::MatrixXi(static_cast<Eigen::Index>(rows.size()), 4)};
  for (std::size_t row = 0; row < rows.size(); ++row)
    for (int corner = 0; corner < 4; ++corner) mesh.cells(static_cast<Eigen::Index>(row), corner) = rows[row][corner];
  return mesh;
}

// Below this fraction of its longest edge cubed, a tetrahedron is a sliver whose pieces'
// rounded volumes may have either sign (a blade nearly parallel to a face leaves such
// slivers): it is left out, losing no more volume than that, so that every kept one and
// its pieces have positive volumes in floating point too and can be cut again.
constexpr double flat_fraction = 1e-14;

bool is_flat(const Eigen::Vector3d& origin, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
             const Eigen::Vector3d& c) {
  if (orientation_sign(a, b, c, origin) >= 0) return true;
  const double longest = std::max(
      {(a - origin).norm(), (b - origin).norm(), (c - origin).norm(), (b - a).norm(), (c - a).norm(), (c - b).norm()});
  return (a - origin).cross(b - origin).dot(c - origin) / 6 <= flat_fraction * longest * longest * longest;
}

bool is_flat(const Eigen::MatrixXd& nodes, const TetrahedronRow& row) {
  return is_flat(nodes.row(row[0]).transpose(), nodes.row(row[1]).transpose(), nodes.row(row[2]).transpose(),
                 nodes.row(row[3]).transpose());
}

bool comes_before(const Eigen::MatrixXd& nodes, int a, int b) {
  for (int axis = 0; axis < 3; ++axis)
    if (nodes(a, axis) != nodes(b, axis)) return nodes(a, axis) < nodes(b, axis);
  return a < b;
}

std::vector<std::vector<int>> outward_loops(const PolyhedralMesh& mesh, int cell) {
  std::vector<std::vector<int>> loops;
  for (const int face : mesh.cell_faces[cell]) {
    std::vector<int> loop = mesh.faces[face];
    if (mesh.face_cells(face, 0) != cell) std::reverse(loop.begin(), loop.end());
    loops.push_back(std::move(loop));
  }
  return loops;
}

CutInput cut_input(const FragmentedTetrahedra& input, int& flat) {
  const VolumeMesh& mesh = input.mesh;
  std::vector<std::vector<int>> tetrahedra_of(static_cast<std::size_t>(input.fragment_count()));
  for (int cell = 0; cell < static_cast<int>(mesh.cells.rows()); ++cell) {
    if (is_flat(mesh.nodes, row_of(mesh, cell))) ++flat;
    else tetrahedra_of[input.fragment_of(cell)].push_back(cell);
  }
  CutInput result;
  std::vector<bool> keep(tetrahedra_of.size());
  for (std::size_t fragment = 0; fragment < keep.size(); ++fragment) keep[fragment] = !tetrahedra_of[fragment].empty();
  if (input.fragments.cell_count() > 0) {
    // Usually every fragment holds a tetrahedron: cut the input's own, not a copy.
    if (std::all_of(keep.begin(), keep.end(), [](bool kept) { return kept; })) {
      result.fragments = &input.fragments;
      result.fragment.resize(keep.size());
      std::iota(result.fragment.begin(), result.fragment.end(), 0);
    } else {
      result.built = polyhedral_mesh_with_cells(input.fragments, keep, result.fragment);
    }
  } else {
    // Each tetrahedron its own fragment: polyhedral_mesh_from_volume_mesh keeps the used
    // nodes in their order.
    VolumeMesh kept{ElementType::tet4, mesh.nodes, Eigen::MatrixXi(mesh.cells.rows(), 4)};
    for (std::size_t fragment = 0; fragment < keep.size(); ++fragment)
      if (keep[fragment]) {
        kept.cells.row(static_cast<Eigen::Index>(result.fragment.size())) =
            mesh.cells.row(static_cast<Eigen::Index>(fragment));
        result.fragment.push_back(static_cast<int>(fragment));
      }
    kept.cells.conservativeResize(static_cast<Eigen::Index>(result.fragment.size()), 4);
    std::vector<bool> used(static_cast<std::size_t>(mesh.nodes.rows()), false);
    for (Eigen::Index cell = 0; cell < kept.cells.rows(); ++cell)
      for (int corner = 0; corner < 4; ++corner) used[kept.cells(cell, corner)] = true;
    for (std::size_t node = 0; node < used.size(); ++node)
      if (used[node]) result.input_node.push_back(static_cast<int>(node));
    result.built = polyhedral_mesh_from_volume_mesh(kept);
  }
  for (const int fragment : result.fragment) result.tetrahedra.push_back(std::move(tetrahedra_of[fragment]));
  return result;
}

std::vector<bool> on_a_face(const PolyhedralMesh& mesh) {
  std::vector<bool> held(static_cast<std::size_t>(mesh.nodes.rows()), false);
  for (const std::vector<int>& loop : mesh.faces)
    for (const int node : loop) held[node] = true;
  return held;
}

void set_result(FragmentedTetrahedra& output, PolyhedralMesh fragments, const std::vector<Eigen::Vector3d>& added,
                const std::vector<TetrahedronRow>& rows) {
  const Eigen::Index first = fragments.nodes.rows();
  fragments.nodes.conservativeResize(first + static_cast<Eigen::Index>(added.size()), 3);
  for (std::size_t node = 0; node < added.size(); ++node)
    fragments.nodes.row(first + static_cast<Eigen::Index>(node)) = added[node].transpose();
  output.mesh = tetrahedra_of_rows(fragments.nodes, rows);
  output.fragments = std::move(fragments);
}

bool carry_tetrahedra(const PolyhedralMesh& pieces, int piece, const std::vector<int>& copied,
                      const std::vector<bool>& inside, const VolumeMesh& input, const std::vector<int>& tetrahedra,
                      std::vector<TetrahedronRow>& rows, std::vector<std::pair<int, int>>& copy_of) {
  copy_of.clear();
  for (const int face : pieces.cell_faces[piece])
    for (const int node : pieces.faces[face])
      if (copied[node] >= 0) copy_of.emplace_back(copied[node], node);
  const std::size_t start = rows.size();
  for (const int tetrahedron : tetrahedra) {
    TetrahedronRow row = row_of(input, tetrahedron);
    for (int& corner : row) {
      if (inside[corner]) continue;  // a cone's apex, no face's: the same node
      // A fragment has a few dozen nodes at most: a linear search, no tree.
      const auto found = std::find_if(copy_of.begin(), copy_of.end(),
                                      [corner](const std::pair<int, int>& copy) { return copy.first == corner; });
      if (found == copy_of.end()) {
        rows.resize(start);
        return false;
      }
      corner = found->second;
    }
    rows.push_back(row);
  }
  return true;
}

std::vector<bool> inside_fragments(const FragmentedTetrahedra& input, const CutInput& fragments) {
  std::vector<bool> inside(static_cast<std::size_t>(input.mesh.nodes.rows()), false);
  if (!fragments.input_node.empty()) return inside;  // each tetrahedron its own fragment
  const std::vector<bool> held = on_a_face(fragments.mesh());
  std::vector<bool> used(inside.size(), false);
  for (Eigen::Index cell = 0; cell < input.mesh.cells.rows(); ++cell)
    for (int corner = 0; corner < 4; ++corner) used[input.mesh.cells(cell, corner)] = true;
  for (std::size_t node = 0; node < inside.size(); ++node) inside[node] = used[node] && !held[node];
  return inside;
}

}  // namespace tetrahedral_cut

using namespace tetrahedral_cut;

FragmentedTetrahedra convex_cells_as_fragments(PolyhedralMesh cells) {
  std::vector<TetrahedronRow> rows;
  FragmentedTetrahedra result;
  int flat = 0;
  ConeTetrahedra cones(cells);
  for (int cell = 0; cell < cells.cell_count(); ++cell) {
    const std::size_t first_row = rows.size();
    cones.split(cell, false, rows, flat);
    result.fragment.insert(result.fragment.end(), rows.size() - first_row, cell);
  }
  cones.set_faces_of(cells);
  set_result(result, std::move(cells), cones.added(), rows);
  return result;
}

int FragmentedTetrahedra::fragment_count() const {
  return fragments.cell_count() > 0 ? fragments.cell_count() : static_cast<int>(mesh.cells.rows());
}

TetrahedralCut cut_tetrahedral_mesh(const FragmentedTetrahedra& input, const CuttingPlane& plane,
                                    const CutScope& scope) {
  if (input.mesh.element_type != ElementType::tet4)
    throw std::invalid_argument("cut_tetrahedral_mesh: the mesh must be of Tet4 cells");
  if (plane.surface) return cut_tetrahedral_mesh_by_surface(input, *plane.surface);
  TetrahedralCut result;
  const CutInput fragments = cut_input(input, result.flat_tetrahedra);
  PolyhedralCut cut = cut_polyhedral_mesh(fragments.mesh(), plane, false, scope);
  result.crossed_fragments = cut.crossed_cells;
  result.joined_fragments = cut.joined_cells;
  result.separated_faces = cut.separated_faces;
  result.duplicated_nodes = cut.duplicated_nodes;
  result.snapped_nodes = cut.snapped_nodes;
  for (const NodeSource& source : cut.node_sources)
    result.node_sources.push_back(
        {fragments.input_node_of(source.first), fragments.input_node_of(source.second), source.weight});

  std::vector<int> copied(result.node_sources.size());
  for (std::size_t node = 0; node < copied.size(); ++node)
    copied[node] = result.node_sources[node].weight == 0 ? result.node_sources[node].first : -1;
  const std::vector<bool> inside = inside_fragments(input, fragments);
  std::vector<int> pieces_of(fragments.tetrahedra.size(), 0);
  for (const int parent : cut.parent_cell) ++pieces_of[parent];
  std::vector<TetrahedronRow> rows;
  ConeTetrahedra cones(cut.mesh);
  std::vector<std::pair<int, int>> copy_of;
  rows.reserve(static_cast<std::size_t>(input.mesh.cells.rows()) + 4 * static_cast<std::size_t>(cut.crossed_cells));
  FragmentedTetrahedra& output = result.result;
  for (int piece = 0; piece < cut.mesh.cell_count(); ++piece) {
    const int parent = cut.parent_cell[piece];
    const std::size_t first_row = rows.size();
    if (pieces_of[parent] > 1 ||
        !carry_tetrahedra(cut.mesh, piece, copied, inside, input.mesh, fragments.tetrahedra[parent], rows, copy_of))
      cones.split(piece, false, rows, result.flat_tetrahedra);
    output.fragment.insert(output.fragment.end(), rows.size() - first_row, piece);
    result.parent_fragment.push_back(fragments.fragment[parent]);
  }
  cones.set_faces_of(cut.mesh);
  set_result(output, std::move(cut.mesh), cones.added(), rows);
  return result;
}

}  // namespace altfem
