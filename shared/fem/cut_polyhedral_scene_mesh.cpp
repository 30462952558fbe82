#include "shared/fem/cut_polyhedral_scene_mesh.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <limits>
#include <optional>

#include "shared/mesh/cut_polyhedral_mesh.hpp"
#include "shared/mesh/cut_surface.hpp"
#include "shared/mesh/merge_slivers.hpp"

namespace altfem {

namespace {

// Whether the polyhedron's vertices lie in one plane, to 1e-8 of its extent: a flat piece
// that a surface blade's steps left on one of its planes (nodes snapped within 1e-9 of the
// body's diagonal, surface_cut_debris.hpp), with a face or two that do not close. It holds
// no volume, and a rule over open faces integrates nothing meaningful (on the ball of
// bench/make_surface_blades.py such pieces lie below 1e-10, every other above 0.1).
bool flat(const Polyhedron& polyhedron) {
  const Eigen::MatrixXd centred = polyhedron.vertices.rowwise() - polyhedron.vertices.colwise().mean();
  const Eigen::VectorXd extents = Eigen::JacobiSVD<Eigen::MatrixXd>(centred).singularValues();
  return extents.size() < 3 || extents[2] <= 1e-8 * extents[0];
}

}  // namespace

PolyhedralSceneMesh cut_polyhedral_scene_mesh(const PolyhedralSceneMesh& mesh, const SceneEvent& cut,
                                              nlohmann::json& facts, const RefusedCells& refused) {
  PolyhedralCut result_of_cut = cut_polyhedral_mesh(mesh.sliced.mesh, cut.blade);
  PolyhedralMesh& pieces = result_of_cut.mesh;
  // The pieces of crossed cells (convex or not) merge below their fraction of the cell.
  std::vector<int> pieces_of_cell(static_cast<std::size_t>(mesh.sliced.mesh.cell_count()), 0);
  for (const int cell : result_of_cut.parent_cell) ++pieces_of_cell[cell];
  std::vector<double> minimum_volume(static_cast<std::size_t>(pieces.cell_count()), 0.0);
  for (int piece = 0; piece < pieces.cell_count(); ++piece) {
    const int cell = result_of_cut.parent_cell[piece];
    if (pieces_of_cell[cell] > 1) minimum_volume[piece] = cut.merge_fraction * mesh.sliced.mesh.cell_volumes(cell);
  }
  // A cell the method refuses merges whatever its volume: its threshold is above any.
  int refused_cells = 0;
  if (refused) {
    std::vector<int> candidates;
    for (int cell = 0; cell < pieces.cell_count(); ++cell)
      if (pieces.cell_volumes(cell) >= minimum_volume[cell]) candidates.push_back(cell);
    const std::vector<bool> refuses = refused(pieces, candidates);
    for (std::size_t k = 0; k < candidates.size(); ++k)
      if (refuses[k]) {
        minimum_volume[candidates[k]] = std::numeric_limits<double>::infinity();
        ++refused_cells;
      }
  }
  // Pieces that merge keep their polyhedra until it is known which merged with pieces of
  // another cell: dg projects its field on those piece by piece (dg_transfer.hpp).
  std::optional<PolyhedralMesh> before_merge;
  for (int piece = 0; piece < pieces.cell_count() && !before_merge; ++piece)
    if (pieces.cell_volumes(piece) < minimum_volume[piece]) before_merge = pieces;
  const MergedPieces merged = merge_small_pieces(pieces, minimum_volume);
  std::vector<NodeSource> node_sources = std::move(result_of_cut.node_sources);
  if (!merged.kept_nodes.empty() && !node_sources.empty()) {  // a surface blade's cut has none
    std::vector<NodeSource> kept;
    for (const int node : merged.kept_nodes) kept.push_back(node_sources[node]);
    node_sources = std::move(kept);
  }
  facts = {{"crossed_cells", result_of_cut.crossed_cells},
           {"joined_cells", result_of_cut.joined_cells},
           {"separated_faces", result_of_cut.separated_faces},
           {"duplicated_nodes", result_of_cut.duplicated_nodes},
           {"snapped_nodes", result_of_cut.snapped_nodes},
           {"merged_pieces", merged.merged + result_of_cut.merged_pieces},
           {"refused_cells", refused_cells},
           {"dropped_pieces", result_of_cut.dropped_pieces},
           {"merged_faces", result_of_cut.merged_faces},
           {"dropped_nodes", result_of_cut.dropped_nodes},
           {"cells", pieces.cell_count()}};
  // Per cell of the result: its parent, the cell before that held it whole (-1: pieces of
  // several merged), and its level, its parent's (merged pieces: the most refined one's).
  std::vector<int> parents(static_cast<std::size_t>(pieces.cell_count()), -2);
  std::vector<int> levels(mesh.cell_levels.empty() ? 0 : parents.size(), 0);
  for (std::size_t piece = 0; piece < result_of_cut.parent_cell.size(); ++piece) {
    const int cell = merged.new_cell.empty() ? static_cast<int>(piece) : merged.new_cell[piece];
    const int parent = result_of_cut.parent_cell[piece];
    parents[cell] = parents[cell] == -2 || parents[cell] == parent ? parent : -1;
    if (!levels.empty()) levels[cell] = std::max(levels[cell], mesh.cell_levels[parent]);
  }
  std::vector<std::vector<ParentPart>> merged_parts;
  if (before_merge && std::find(parents.begin(), parents.end(), -1) != parents.end()) {
    merged_parts.resize(parents.size());
    for (int piece = 0; piece < before_merge->cell_count(); ++piece) {
      const int cell = merged.new_cell[piece];
      Polyhedron polyhedron = cell_polyhedron(*before_merge, piece);
      if (parents[cell] == -1 && !flat(polyhedron))
        merged_parts[cell].push_back({result_of_cut.parent_cell[piece], std::move(polyhedron)});
    }
  }
  PolyhedralSceneMesh result = mesh;
  // The surface it deforms when it is its own (the geometry has none in common), cut by
  // the same blade, as Simulation cuts the common one every method deforms.
  if (mesh.surface.triangles.rows() > 0) result.surface = cut_surface(mesh.surface, cut.blade).surface;
  result.cell_levels = std::move(levels);
  result.sliced.mesh = std::move(pieces);
  result.converted.reset();
  result.node_sources = std::move(node_sources);
  result.parent_cells = std::move(parents);
  result.merged_parts = std::move(merged_parts);
  return result;
}

}  // namespace altfem
