#include "shared/mesh/cut_tetrahedral_mesh.hpp"

#include <algorithm>
#include <array>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <utility>

#include "shared/common/error.hpp"
#include "shared/geometry/exact_orientation.hpp"
#include "shared/mesh/cut_by_surface.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"

namespace altfem {
namespace {

using TetrahedronRow = std::array<int, 4>;

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

// Flat: not positively oriented (exact predicate) or a sliver by its rounded volume.
bool is_flat(const Eigen::MatrixXd& nodes, const TetrahedronRow& row) {
  const Eigen::Vector3d origin = nodes.row(row[0]), a = nodes.row(row[1]), b = nodes.row(row[2]), c = nodes.row(row[3]);
  if (orientation_sign(a, b, c, origin) >= 0) return true;
  const double longest = std::max(
      {(a - origin).norm(), (b - origin).norm(), (c - origin).norm(), (b - a).norm(), (c - a).norm(), (c - b).norm()});
  return (a - origin).cross(b - origin).dot(c - origin) / 6 <= flat_fraction * longest * longest * longest;
}

// Node a before node b by position (lexicographic coordinates; equal positions by index):
// an order no cut changes, since nodes never move and a copy sits where its node does, so
// a face fanned from its first node is fanned alike before and after any later cut.
bool comes_before(const Eigen::MatrixXd& nodes, int a, int b) {
  for (int axis = 0; axis < 3; ++axis)
    if (nodes(a, axis) != nodes(b, axis)) return nodes(a, axis) < nodes(b, axis);
  return a < b;
}

// The cell's node loops, each counter-clockwise seen from outside it.
std::vector<std::vector<int>> outward_loops(const PolyhedralMesh& mesh, int cell) {
  std::vector<std::vector<int>> loops;
  for (const int face : mesh.cell_faces[cell]) {
    std::vector<int> loop = mesh.faces[face];
    if (mesh.face_cells(face, 0) != cell) std::reverse(loop.begin(), loop.end());
    loops.push_back(std::move(loop));
  }
  return loops;
}

// The input's fragments that hold a tetrahedron that is not flat, as the polyhedral mesh
// the blade cuts: per kept fragment its input index and non-flat tetrahedra, and per
// node of that mesh its input node.
struct CutInput {
  std::optional<PolyhedralMesh> built;        ///< when not the input's own fragments, whole
  const PolyhedralMesh* fragments = nullptr;  ///< the input's, when it keeps every one
  std::vector<int> fragment;                  ///< per cell of mesh()
  std::vector<std::vector<int>> tetrahedra;   ///< per cell of mesh()
  std::vector<int> input_node;                ///< per node of mesh(); empty: the same numbers

  const PolyhedralMesh& mesh() const { return built ? *built : *fragments; }
  int input_node_of(int node) const { return input_node.empty() ? node : input_node[node]; }
};

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

// The tetrahedra of a convex piece: a cone from its first node (by position) over the
// faces that do not hold it, each fanned from its own first node; flat ones left out.
void split_into_tetrahedra(const PolyhedralMesh& pieces, int piece, std::vector<TetrahedronRow>& rows, int& flat) {
  const Eigen::MatrixXd& nodes = pieces.nodes;
  const auto before = [&](int a, int b) { return comes_before(nodes, a, b); };
  const std::vector<std::vector<int>> loops = outward_loops(pieces, piece);
  int apex = loops[0][0];
  for (const auto& loop : loops) apex = std::min(apex, *std::min_element(loop.begin(), loop.end(), before), before);
  for (std::vector<int> loop : loops) {
    if (std::find(loop.begin(), loop.end(), apex) != loop.end()) continue;
    std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end(), before), loop.end());
    for (std::size_t k = 1; k + 1 < loop.size(); ++k) {
      const TetrahedronRow row{apex, loop[0], loop[k], loop[k + 1]};
      if (is_flat(nodes, row)) ++flat;
      else rows.push_back(row);
    }
  }
}

// The input tetrahedra of a piece the blade did not cross, each corner taken as the copy
// of its node that the piece holds; false when a corner has none (then it is split afresh).
// `copy_of`: scratch, (input node, the piece's copy) pairs, reused from piece to piece.
bool carry_tetrahedra(const PolyhedralMesh& pieces, int piece, const std::vector<NodeSource>& sources,
                      const VolumeMesh& input, const std::vector<int>& tetrahedra, std::vector<TetrahedronRow>& rows,
                      std::vector<std::pair<int, int>>& copy_of) {
  copy_of.clear();
  for (const int face : pieces.cell_faces[piece])
    for (const int node : pieces.faces[face])
      if (sources[node].weight == 0) copy_of.emplace_back(sources[node].first, node);
  const std::size_t start = rows.size();
  for (const int tetrahedron : tetrahedra) {
    TetrahedronRow row = row_of(input, tetrahedron);
    for (int& corner : row) {
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

}  // namespace

FragmentedTetrahedra convex_cells_as_fragments(PolyhedralMesh cells) {
  std::vector<TetrahedronRow> rows;
  FragmentedTetrahedra result;
  int flat = 0;
  for (int cell = 0; cell < cells.cell_count(); ++cell) {
    const std::size_t first_row = rows.size();
    split_into_tetrahedra(cells, cell, rows, flat);
    result.fragment.insert(result.fragment.end(), rows.size() - first_row, cell);
  }
  result.mesh = tetrahedra_of_rows(cells.nodes, rows);
  result.fragments = std::move(cells);
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

  std::vector<int> pieces_of(fragments.tetrahedra.size(), 0);
  for (const int parent : cut.parent_cell) ++pieces_of[parent];
  std::vector<TetrahedronRow> rows;
  std::vector<std::pair<int, int>> copy_of;
  rows.reserve(static_cast<std::size_t>(input.mesh.cells.rows()) + 4 * static_cast<std::size_t>(cut.crossed_cells));
  FragmentedTetrahedra& output = result.result;
  for (int piece = 0; piece < cut.mesh.cell_count(); ++piece) {
    const int parent = cut.parent_cell[piece];
    const std::size_t first_row = rows.size();
    if (pieces_of[parent] > 1 || !carry_tetrahedra(cut.mesh, piece, result.node_sources, input.mesh,
                                                   fragments.tetrahedra[parent], rows, copy_of))
      split_into_tetrahedra(cut.mesh, piece, rows, result.flat_tetrahedra);
    output.fragment.insert(output.fragment.end(), rows.size() - first_row, piece);
    result.parent_fragment.push_back(fragments.fragment[parent]);
  }
  output.mesh = tetrahedra_of_rows(cut.mesh.nodes, rows);
  output.fragments = std::move(cut.mesh);
  return result;
}

TetrahedralCut cut_tetrahedral_mesh_by_surface(const FragmentedTetrahedra& input, const SurfaceBlade& blade) {
  TetrahedralCut result;
  result.result = input;
  result.parent_fragment.resize(static_cast<std::size_t>(input.fragment_count()));
  std::iota(result.parent_fragment.begin(), result.parent_fragment.end(), 0);
  Eigen::AlignedBox3d bounds;
  for (Eigen::Index node = 0; node < input.mesh.nodes.rows(); ++node)
    bounds.extend(input.mesh.nodes.row(node).transpose());
  TrianglePlaneNodes on_plane;
  const int fragment_limit = 50 * input.fragment_count() + 100000;
  for (const SurfaceBladeStep& blade_step : surface_blade_steps(blade)) {
    if (!blade_step.scope.region->intersects(bounds)) continue;
    CutScope scope = on_plane.scope_for(blade_step);
    // A fragment left whole keeps its faces: a face split for one side only would hold a
    // node in the middle of an edge of the other's, which no fan of its faces conforms to.
    scope.spread = true;
    const Eigen::Index nodes_before = result.result.mesh.nodes.rows();
    TetrahedralCut step = cut_snapping_less_if_need_be(
        [&](const CutScope& tried) { return cut_tetrahedral_mesh(result.result, blade_step.plane, tried); }, scope);
    on_plane.after(blade_step, step.result.mesh.nodes, step.node_sources, nodes_before);
    fold_step_counts(result, step, result.parent_fragment, step.parent_fragment);
    result.result = std::move(step.result);
    result.flat_tetrahedra += step.flat_tetrahedra;
    // Each split spreads through the body, so a blade whose triangles lie in many planes
    // (a closed or finely curved one) multiplies the fragments: stop before that runs for
    // hours or fills the memory.
    if (result.result.fragment_count() > fragment_limit)
      throw NumericalError("cut: the surface blade's " + std::to_string(blade.triangles.rows()) +
                           " triangles split the embedded tetrahedra into more than " + std::to_string(fragment_limit) +
                           " fragments (from " + std::to_string(input.fragment_count()) +
                           "): each triangle's planes cut them through the body; a blade of fewer planes, or the "
                           "dg and harmonic methods, which split only the cells near each triangle");
  }
  std::vector<int> pieces_of(static_cast<std::size_t>(input.fragment_count()), 0);
  for (const int parent : result.parent_fragment) ++pieces_of[parent];
  for (const int pieces : pieces_of) result.crossed_fragments += pieces > 1 ? 1 : 0;
  return result;
}

}  // namespace altfem
