#include "shared/cut_cells/embedded_cut_cells.hpp"

#include <algorithm>
#include <chrono>

#include "shared/cut_cells/cell_pieces.hpp"
#include "shared/cut_cells/piece_basis_evaluator.hpp"
#include "shared/cut_cells/piece_dirichlet.hpp"
#include "shared/cut_cells/region_cut_check.hpp"
#include "shared/fem/lagrange_basis_evaluator.hpp"
#include "shared/mesh/cut_tetrahedral_mesh.hpp"
#include "shared/simulation/nodal_basis.hpp"

namespace altfem {

namespace {

// The rows of node n of `moved` from those of node origin[n] of `fields`, where origin[n] ≥ 0.
void copy_node_values(const std::vector<int>& origin, const Eigen::MatrixXd& fields, Eigen::MatrixXd& moved) {
  for (std::size_t node = 0; node < origin.size(); ++node)
    if (origin[node] >= 0)
      moved.middleRows(3 * static_cast<Eigen::Index>(node), 3) =
          fields.middleRows(3 * static_cast<Eigen::Index>(origin[node]), 3);
}

// The volume of one cell of `mesh` from its own nodes (volume_mesh_volume of that cell
// alone, without copying every node of the mesh).
double cell_volume(const VolumeMesh& mesh, Eigen::Index cell) {
  VolumeMesh alone{mesh.element_type, Eigen::MatrixXd(mesh.cells.cols(), 3), Eigen::MatrixXi(1, mesh.cells.cols())};
  for (Eigen::Index k = 0; k < mesh.cells.cols(); ++k) {
    alone.nodes.row(k) = mesh.nodes.row(mesh.cells(cell, k));
    alone.cells(0, k) = static_cast<int>(k);
  }
  return volume_mesh_volume(alone);
}

}  // namespace

EmbeddedCutCells::EmbeddedCutCells(const VolumeMesh& background, EmbeddedTetrahedra embedded,
                                   const CutCellSettings& settings, const SceneMaterials& materials,
                                   const std::vector<DirichletCondition>& dirichlet, const std::string& scene_file,
                                   const CutCellRebuild& rebuild)
    : settings_(settings), background_(background), embedded_(std::move(embedded)) {
  const RefinedBackground* refined = rebuild.refined;
  const auto start = std::chrono::steady_clock::now();
  // Topology-aware cells (Longva et al. 2020 §7's limitation): one cell per piece of
  // material, each clipping only its own tetrahedra, with node copies per part.
  VolumeMesh cells = background;
  std::vector<std::vector<int>> cell_tetrahedra;
  std::vector<char> filled_cells;
  if (settings.topology_aware) {
    if (rebuild.remember_clips) clip_memory_ = std::make_shared<ClippedTetrahedronMemory>();
    const CellPieces pieces = find_cell_pieces(background, embedded_.mesh(), refined ? &refined->contacts : nullptr,
                                               rebuild.clips.get(), clip_memory_.get());
    split_cells_ = pieces.split_cells();
    pieces_ = piece_mesh(background, pieces);
    cells = pieces_->mesh;
    cell_tetrahedra = pieces_->tetrahedra;
    filled_cells = pieces_->filled;
    topology_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  statistics_ = std::make_shared<IntersectionStatistics>();
  rule_memory_ = std::make_shared<CellRuleMemory>();
  const CellQuadratureSource rules = intersection_cell_quadrature(
      cells, embedded_.mesh(), settings.simplifier, settings.simplification_tolerance, {}, statistics_,
      std::move(cell_tetrahedra), std::move(filled_cells), rebuild.rules, rule_memory_);
  BackgroundHangingNodes hanging;
  if (refined)
    hanging = {&refined->sources, refined->free_nodes, pieces_ ? pieces_->background_node : std::vector<int>{},
               pieces_ ? pieces_->background_cell : std::vector<int>{}};
  fcm_ = build_fcm_discretization(
      cells, rules, materials.pointers(), materials.ids_of(corner_centroids(cells)), dirichlet, settings.options,
      scene_file, pieces_ ? piece_dirichlet_nodes(*pieces_, embedded_.mesh()) : NodeRegionFilter{}, hanging);
  warnings_ = conditions_cutting_cells(fcm_.mesh, dirichlet);
  for (std::size_t cell = 0; cell < fcm_.volume_fractions.size(); ++cell)
    material_volume_ += fcm_.volume_fractions[cell] * cell_volume(fcm_.mesh, static_cast<Eigen::Index>(cell));
  seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::unique_ptr<ElementBasisEvaluator> EmbeddedCutCells::basis_evaluator() const {
  const NodeConstraints* constraints = fcm_.constraints.empty() ? nullptr : &fcm_.constraints;
  if (pieces_)
    return std::make_unique<PieceBasisEvaluator>(fcm_.mesh, *pieces_, fcm_.background_cells, embedded_.mesh(),
                                                 constraints);
  return std::make_unique<LagrangeBasisEvaluator>(fcm_.mesh, constraints);
}

UnstructuredGrid EmbeddedCutCells::volume_grid(const Eigen::VectorXd& displacement) const {
  UnstructuredGrid grid = grid_from_volume_mesh(fcm_.mesh);
  add_nodal_displacement(grid, fcm_.constraints.all_nodes(displacement));
  grid.cell_data.emplace_back(
      "volume_fraction", Eigen::Map<const Eigen::VectorXd>(fcm_.volume_fractions.data(), fcm_.volume_fractions.size()));
  const TabulatedElements& elements = fcm_.discretization->elements();
  Eigen::VectorXd points(elements.size());
  for (int e = 0; e < elements.size(); ++e) points[e] = elements.whole_point_count(e);
  grid.cell_data.emplace_back("quadrature_points", points);
  // Which piece of its background cell a kept cell is (0 unless the cell is split).
  Eigen::VectorXd piece = Eigen::VectorXd::Zero(elements.size());
  if (pieces_)
    for (int e = 0; e < elements.size(); ++e) piece[e] = pieces_->piece[fcm_.background_cells[e]];
  grid.cell_data.emplace_back("piece", piece);
  return grid;
}

nlohmann::json EmbeddedCutCells::facts() const {
  return {{"cells",
           {{"inside", fcm_.counts.inside},
            {"cut", fcm_.counts.cut},
            {"discarded", fcm_.counts.discarded},
            {"split", split_cells_},
            {"outside", fcm_.counts.outside}}},
          {"cut_cell_points", {{"initial", statistics_->initial_points}, {"final", statistics_->final_points}}},
          {"worst_moment_residual", statistics_->max_residual},
          {"failed_simplifications", statistics_->failed_simplifications},
          {"rule_generation_s", statistics_->seconds},
          {"reused_cell_rules", statistics_->reused_cells},
          {"integrated_cell_rules", statistics_->integrated_cells},
          {"reused_mass_tetrahedra", statistics_->reused_mass_tetrahedra},
          {"piece_finding_s", topology_seconds_},
          {"split_nodes", pieces_ ? pieces_->split_nodes() : 0},
          {"schwarz_blocks", fcm_.schwarz_blocks},
          {"ghost_penalty_faces", fcm_.ghost ? fcm_.ghost->faces.size() : 0}};
}

std::vector<int> EmbeddedCutCells::background_cell_of_kept() const {
  std::vector<int> cells = fcm_.background_cells;
  if (pieces_)
    for (int& cell : cells) cell = pieces_->background_cell[cell];
  return cells;
}

std::string EmbeddedCutCells::cut_refusal() const {
  return pieces_ ? "" : "it cuts with topology-aware cells only (/discretization/fcm/topology_aware is false)";
}

// The blade cuts the embedded tetrahedra (issue #33); the rebuild finds the cells' pieces
// again, so a cell whose material the blade separates gets a node copy per side.
EmbeddedTetrahedra EmbeddedCutCells::cut(const CuttingPlane& blade, nlohmann::json& facts) const {
  return cut_embedded_tetrahedra(embedded_.material, blade, facts);
}

EmbeddedTetrahedra cut_embedded_tetrahedra(const FragmentedTetrahedra& material, const CuttingPlane& blade,
                                           nlohmann::json& facts) {
  TetrahedralCut cut = cut_tetrahedral_mesh(material, blade);
  facts = {{"crossed_fragments", cut.crossed_fragments}, {"joined_fragments", cut.joined_fragments},
           {"separated_faces", cut.separated_faces},     {"duplicated_nodes", cut.duplicated_nodes},
           {"snapped_nodes", cut.snapped_nodes},         {"flat_tetrahedra", cut.flat_tetrahedra},
           {"dropped_fragments", cut.dropped_fragments}, {"fragments", cut.result.fragment_count()},
           {"tetrahedra", cut.result.mesh.cells.rows()}};
  return {std::move(cut.result), std::move(cut.parent_fragment)};
}

// Built on `before`'s background and embedded tetrahedra, or on a cut of them (another
// background, e.g. a finer one, shares no lineage).
bool EmbeddedCutCells::continues(const EmbeddedCutCells& before) const {
  const auto same = [](const auto& a, const auto& b) { return a.rows() == b.rows() && a.cols() == b.cols() && a == b; };
  if (!pieces_ || !before.pieces_ || !same(background_.cells, before.background_.cells) ||
      !same(background_.nodes, before.background_.nodes))
    return false;
  if (embedded_.parent.empty()) return same(embedded_.mesh().cells, before.embedded_.mesh().cells);
  return *std::max_element(embedded_.parent.begin(), embedded_.parent.end()) <
         before.embedded_.material.fragment_count();
}

std::vector<int> EmbeddedCutCells::node_origins(const EmbeddedCutCells& before) const {
  if (!continues(before)) return {};
  const PieceMesh& old_pieces = *before.pieces_;
  std::vector<int> old_kept(old_pieces.mesh.cells.rows(), -1);
  for (std::size_t cell = 0; cell < before.fcm_.background_cells.size(); ++cell)
    old_kept[before.fcm_.background_cells[cell]] = static_cast<int>(cell);
  std::vector<std::vector<int>> old_pieces_of(static_cast<std::size_t>(background_.cells.rows()));
  for (std::size_t piece = 0; piece < old_pieces.background_cell.size(); ++piece)
    old_pieces_of[old_pieces.background_cell[piece]].push_back(static_cast<int>(piece));
  std::vector<int> origin(static_cast<std::size_t>(fcm_.mesh.nodes.rows()), -1);
  for (std::size_t cell = 0; cell < fcm_.background_cells.size(); ++cell) {
    const int piece = fcm_.background_cells[cell];
    const std::vector<int>& tetrahedra = pieces_->tetrahedra[piece];
    if (tetrahedra.empty()) continue;
    // The fragment before the cut that the piece's first tetrahedron lies in: convex, so
    // its part in this background cell lay in one piece there.
    const int fragment = embedded_.material.fragment_of(tetrahedra.front());
    const int parent = embedded_.parent.empty() ? fragment : embedded_.parent[fragment];
    const FragmentedTetrahedra& old_material = before.embedded_.material;
    for (const int old_piece : old_pieces_of[pieces_->background_cell[piece]]) {
      const std::vector<int>& old_tetrahedra = old_pieces.tetrahedra[old_piece];
      if (std::none_of(old_tetrahedra.begin(), old_tetrahedra.end(),
                       [&](int old) { return old_material.fragment_of(old) == parent; }))
        continue;
      const int old_cell = old_kept[old_piece];
      if (old_cell >= 0)
        for (Eigen::Index k = 0; k < fcm_.mesh.cells.cols(); ++k)
          origin[fcm_.mesh.cells(static_cast<Eigen::Index>(cell), k)] = before.fcm_.mesh.cells(old_cell, k);
      break;
    }
  }
  return origin;
}

std::vector<int> EmbeddedCutCells::background_nodes() const {
  std::vector<int> nodes(static_cast<std::size_t>(fcm_.mesh.nodes.rows()), -1);
  for (std::size_t cell = 0; cell < fcm_.background_cells.size(); ++cell) {
    const int row = fcm_.background_cells[cell];
    for (Eigen::Index k = 0; k < fcm_.mesh.cells.cols(); ++k) {
      const int node = pieces_ ? pieces_->background_node[pieces_->mesh.cells(row, k)] : background_.cells(row, k);
      nodes[fcm_.mesh.cells(static_cast<Eigen::Index>(cell), k)] = node;
    }
  }
  return nodes;
}

Eigen::MatrixXd EmbeddedCutCells::transfer(const EmbeddedCutCells& before, const ElementBasisEvaluator& before_basis,
                                           const Eigen::MatrixXd& fields) const {
  const auto free_nodes = [](const FcmDiscretization& fcm) {
    return fcm.mesh.nodes.topRows(fcm.constraints.free_nodes);
  };
  if (!fcm_.constraints.empty() || !before.fcm_.constraints.empty())
    return transfer_to_nodes(free_nodes(fcm_), free_nodes(before.fcm_), before_basis, fields);
  const std::vector<int> origin = node_origins(before);
  const bool every_node_continues =
      !origin.empty() && std::none_of(origin.begin(), origin.end(), [](int node) { return node < 0; });
  Eigen::MatrixXd moved = every_node_continues
                              ? Eigen::MatrixXd(3 * fcm_.mesh.nodes.rows(), fields.cols())
                              : transfer_to_nodes(fcm_.mesh.nodes, before.fcm_.mesh.nodes, before_basis, fields);
  copy_node_values(origin, fields, moved);
  return moved;
}

Eigen::MatrixXd EmbeddedCutCells::transfer_from_background(const Eigen::MatrixXd& fields) const {
  Eigen::MatrixXd moved(3 * fcm_.mesh.nodes.rows(), fields.cols());
  copy_node_values(background_nodes(), fields, moved);  // every kept node copies one
  return moved;
}

}  // namespace altfem
