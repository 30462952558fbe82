#include "fcm/fcm_method.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>

#include "fcm/cell_pieces.hpp"
#include "fcm/embedded_mesh.hpp"
#include "fcm/fcm_scene_block.hpp"
#include "fcm/intersection_cell_quadrature.hpp"
#include "fcm/piece_basis_evaluator.hpp"
#include "fcm/piece_dirichlet.hpp"
#include "fcm/piece_mesh.hpp"
#include "fcm/region_cut_check.hpp"
#include "shared/common/error.hpp"
#include "shared/fem/lagrange_basis_evaluator.hpp"
#include "shared/mesh/boundary_surface.hpp"
#include "shared/mesh/cut_tetrahedral_mesh.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "shared/simulation/basis_embedding.hpp"
#include "shared/simulation/embedded_surface.hpp"
#include "shared/simulation/nodal_basis.hpp"
#include "shared/simulation/scene_materials.hpp"

namespace altfem::fcm {

namespace {

// What the method is built on: the background cells (§3.2) and the object as
// embedded tetrahedra (§4.5).
struct FcmMesh {
  VolumeMesh background;
  std::optional<Eigen::Vector3i> resolution;  ///< nullopt: a background mesh file
  VolumeMesh embedded;
  /// Per embedded tetrahedron, the tetrahedron of the instance it was handed by that it
  /// lies in (a cut's pieces); empty when the tetrahedra are that instance's own.
  std::vector<int> parent_tetrahedron;
};

class FcmMethod final : public EmbeddedSurfaceMethod {
public:
  // On the meshes of the scene, or on meshes an event hands it.
  FcmMethod(const Scene& scene, const SceneGeometry& geometry, const FcmMesh* handed) : materials_(scene) {
    const FcmSpec spec = fcm_spec(scene);
    quadrature_strength_ = spec.options.quadrature_strength;
    const std::string file = scene.file.string();
    VolumeMesh background;
    if (handed) {
      background = handed->background;
      resolution_ = handed->resolution;
      embedded_ = handed->embedded;
      parent_tetrahedron_ = handed->parent_tetrahedron;
    } else {
      // The background grid over the geometry's bounds, or the user's mesh (§3.2).
      BackgroundMesh generated = background_mesh(spec, geometry.bounds);
      background = std::move(generated.mesh);
      resolution_ = generated.resolution;
      // The object as tetrahedra (§4.5): the scene's tet mesh, or Mesh_3 of its surface
      // or shape at the same default size as fem's, so both deform the same surface.
      const double embedded_size = spec.embedded_cell_size.value_or(geometry.bounds.diagonal().norm() / 15.0);
      embedded_ = embedded_tetrahedra(geometry, embedded_size, file);
    }
    background_ = background;
    background_cells_ = background.cells.rows();

    const auto start = std::chrono::steady_clock::now();
    // Topology-aware cells (§7's limitation): the grid becomes one cell per piece of
    // material, each clipping only its own tetrahedra, with node copies per part.
    std::vector<std::vector<int>> cell_tetrahedra;
    if (spec.topology_aware) {
      const CellPieces pieces = find_cell_pieces(background, embedded_);
      split_cells_ = pieces.split_cells();
      pieces_ = piece_mesh(background, pieces);
      background = pieces_->mesh;
      cell_tetrahedra = pieces_->tetrahedra;
      topology_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    statistics_ = std::make_shared<IntersectionStatistics>();
    const CellQuadratureSource rules =
        intersection_cell_quadrature(background, embedded_, spec.simplifier, spec.simplification_tolerance, {},
                                     statistics_, std::move(cell_tetrahedra));
    fcm_ = build_fcm_discretization(background, rules, materials_.pointers(),
                                    materials_.ids_of(corner_centroids(background)), scene.dirichlet, spec.options,
                                    file, pieces_ ? piece_dirichlet_nodes(*pieces_, embedded_) : NodeRegionFilter{});
    warnings_ = conditions_cutting_cells(fcm_.mesh, scene.dirichlet);
    for (std::size_t cell = 0; cell < fcm_.volume_fractions.size(); ++cell)
      material_volume_ +=
          fcm_.volume_fractions[cell] * volume_mesh_volume({fcm_.mesh.element_type, fcm_.mesh.nodes,
                                                            fcm_.mesh.cells.row(static_cast<Eigen::Index>(cell))});
    quadrature_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    // The surface every method deforms: the scene's own, else the boundary of the
    // embedded mesh. Points in discarded cells take the nearest kept cell's basis (§5.3).
    // Surface loads act on the boundary of the domain integrated: the embedded tetrahedra's.
    surface_.load_surface = boundary_surface(embedded_).surface;
    surface_.surface = geometry.common_surface() ? *geometry.common_surface() : surface_.load_surface;
    if (pieces_)
      surface_.evaluator = std::make_unique<PieceBasisEvaluator>(fcm_.mesh, *pieces_, fcm_.background_cells, embedded_);
    else surface_.evaluator = std::make_unique<LagrangeBasisEvaluator>(fcm_.mesh);
    surface_.embedding = std::make_unique<BasisEmbedding>(*surface_.evaluator, surface_.surface.vertices);
  }

  const Discretization& discretization() const override { return *fcm_.discretization; }
  nlohmann::json element_counts() const override {
    return {{std::string(element_name(fcm_.mesh.element_type)), fcm_.mesh.cells.rows()}};
  }
  long long quadrature_points() const override { return fcm_.discretization->elements().point_count(); }
  double quadrature_seconds() const override { return quadrature_seconds_; }
  UnstructuredGrid volume_grid(const Eigen::VectorXd& displacement) const override {
    UnstructuredGrid grid = grid_from_volume_mesh(fcm_.mesh);
    add_nodal_displacement(grid, displacement);
    grid.cell_data.emplace_back("volume_fraction", Eigen::Map<const Eigen::VectorXd>(fcm_.volume_fractions.data(),
                                                                                     fcm_.volume_fractions.size()));
    const TabulatedElements& elements = fcm_.discretization->elements();
    Eigen::VectorXd points(elements.size());
    for (int e = 0; e < elements.size(); ++e) points[e] = elements[e].point_count();
    grid.cell_data.emplace_back("quadrature_points", points);
    // Which piece of its background cell a kept cell is (0 unless the cell is split).
    Eigen::VectorXd piece = Eigen::VectorXd::Zero(elements.size());
    if (pieces_)
      for (int e = 0; e < elements.size(); ++e) piece[e] = pieces_->piece[fcm_.background_cells[e]];
    grid.cell_data.emplace_back("piece", piece);
    return grid;
  }
  Eigen::VectorXd interpolate(const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& field) const override {
    return interpolate_at_nodes(fcm_.mesh.nodes, field);
  }
  std::vector<std::string> warnings() const override { return warnings_; }
  std::shared_ptr<const MethodMesh> mesh() const override {
    return std::make_shared<MeshOf<FcmMesh>>(FcmMesh{background_, resolution_, embedded_, {}});
  }
  /// The material's volume Σ vol(K ∩ Ω) over the kept cells: without the fictitious
  /// parts that the stabilisation weighs by α (§5.3), which a cut adds to each new piece.
  std::optional<double> volume() const override { return material_volume_; }
  std::string cut_refusal() const override {
    return pieces_ ? "" : "it cuts with topology-aware cells only (/discretization/fcm/topology_aware is false)";
  }
  /// The blade cuts the embedded tetrahedra (issue #33); the rebuild finds the cells'
  /// pieces again, so a cell whose material the blade separates gets a node copy per side.
  std::shared_ptr<const MethodMesh> cut_mesh(const CuttingPlane& blade, nlohmann::json& facts) const override {
    TetrahedralCut cut = cut_tetrahedral_mesh(embedded_, blade);
    facts = {{"crossed_tetrahedra", cut.crossed_tetrahedra}, {"separated_faces", cut.separated_faces},
             {"duplicated_nodes", cut.duplicated_nodes},     {"snapped_nodes", cut.snapped_nodes},
             {"flat_tetrahedra", cut.flat_tetrahedra},       {"tetrahedra", cut.mesh.cells.rows()}};
    return std::make_shared<MeshOf<FcmMesh>>(
        FcmMesh{background_, resolution_, std::move(cut.mesh), std::move(cut.parent_tetrahedron)});
  }
  /// Nodal values at the nodes (transfer_to_nodes); after a cut a node copy takes the
  /// values of the copy its material came from, which a position cannot tell apart.
  Eigen::MatrixXd transfer(const MethodInstance& previous, const Eigen::MatrixXd& fields) const override {
    const auto& before = dynamic_cast<const FcmMethod&>(previous);
    Eigen::MatrixXd moved =
        transfer_to_nodes(fcm_.mesh.nodes, before.fcm_.mesh.nodes, before.basis_evaluator(), fields);
    if (!pieces_ || !before.pieces_ || !handed_by(before)) return moved;
    const std::vector<int> origin = node_origins(before);
    for (std::size_t node = 0; node < origin.size(); ++node)
      if (origin[node] >= 0)
        moved.middleRows(3 * static_cast<Eigen::Index>(node), 3) =
            fields.middleRows(3 * static_cast<Eigen::Index>(origin[node]), 3);
    return moved;
  }
  /// The stiffness rules at any requested strength: cut cells' rules are simplified to
  /// match the moments up to that strength only (§4), so no stronger rule is at hand. The
  /// stabilising points (§5.3, weights × `stabilization`) are included.
  std::optional<FieldQuadrature> field_quadrature(int /*added_strength*/) const override {
    return nodal_field_quadrature(borrowed(fcm_.discretization->elements()), fcm_.mesh.nodes, quadrature_strength_);
  }
  nlohmann::json facts() const override {
    nlohmann::json facts = surface_.facts();
    facts.update(
        {{"background_cells", background_cells_},
         {"background_resolution",
          resolution_ ? nlohmann::json{resolution_->x(), resolution_->y(), resolution_->z()} : nlohmann::json("file")},
         {"cells",
          {{"inside", fcm_.counts.inside},
           {"cut", fcm_.counts.cut},
           {"discarded", fcm_.counts.discarded},
           {"split", split_cells_},
           {"outside", fcm_.counts.outside}}},
         {"cut_cell_points", {{"initial", statistics_->initial_points}, {"final", statistics_->final_points}}},
         {"worst_moment_residual", statistics_->max_residual},
         {"failed_simplifications", statistics_->failed_simplifications},
         {"rule_generation_s", statistics_->seconds},
         {"piece_finding_s", topology_seconds_},
         {"split_nodes", pieces_ ? pieces_->split_nodes() : 0},
         {"schwarz_blocks", fcm_.schwarz_blocks},
         {"ghost_penalty_faces", fcm_.ghost ? fcm_.ghost->faces.size() : 0}});
    return facts;
  }

private:
  /// Whether this instance was built on `before`'s background and embedded tetrahedra,
  /// or on a cut of them (another background, e.g. a finer one, shares no lineage).
  bool handed_by(const FcmMethod& before) const {
    const auto same = [](const auto& a, const auto& b) {
      return a.rows() == b.rows() && a.cols() == b.cols() && a == b;
    };
    if (!same(background_.cells, before.background_.cells) || !same(background_.nodes, before.background_.nodes))
      return false;
    if (parent_tetrahedron_.empty()) return same(embedded_.cells, before.embedded_.cells);
    return *std::max_element(parent_tetrahedron_.begin(), parent_tetrahedron_.end()) < before.embedded_.cells.rows();
  }
  /// Per kept node, the kept node of `before` (the instance this one was handed the
  /// embedded tetrahedra by) it copies: a kept cell's tetrahedra lie in one piece of the
  /// same background cell before, whose kept cell has the node at the same corner; −1
  /// where that piece was not kept.
  std::vector<int> node_origins(const FcmMethod& before) const {
    const PieceMesh& old_pieces = *before.pieces_;
    std::vector<int> old_kept(old_pieces.mesh.cells.rows(), -1);
    for (std::size_t cell = 0; cell < before.fcm_.background_cells.size(); ++cell)
      old_kept[before.fcm_.background_cells[cell]] = static_cast<int>(cell);
    std::vector<std::vector<int>> old_pieces_of(static_cast<std::size_t>(background_cells_));
    for (std::size_t piece = 0; piece < old_pieces.background_cell.size(); ++piece)
      old_pieces_of[old_pieces.background_cell[piece]].push_back(static_cast<int>(piece));
    std::vector<int> origin(static_cast<std::size_t>(fcm_.mesh.nodes.rows()), -1);
    for (std::size_t cell = 0; cell < fcm_.background_cells.size(); ++cell) {
      const int piece = fcm_.background_cells[cell];
      const std::vector<int>& tetrahedra = pieces_->tetrahedra[piece];
      if (tetrahedra.empty()) continue;
      const int parent = parent_tetrahedron_.empty() ? tetrahedra.front() : parent_tetrahedron_[tetrahedra.front()];
      for (const int old_piece : old_pieces_of[pieces_->background_cell[piece]]) {
        const std::vector<int>& old_tetrahedra = old_pieces.tetrahedra[old_piece];
        if (!std::binary_search(old_tetrahedra.begin(), old_tetrahedra.end(), parent)) continue;
        const int old_cell = old_kept[old_piece];
        if (old_cell >= 0)
          for (Eigen::Index k = 0; k < fcm_.mesh.cells.cols(); ++k)
            origin[fcm_.mesh.cells(static_cast<Eigen::Index>(cell), k)] = before.fcm_.mesh.cells(old_cell, k);
        break;
      }
    }
    return origin;
  }

  SceneMaterials materials_;
  std::optional<Eigen::Vector3i> resolution_;  ///< nullopt: a background mesh file
  VolumeMesh background_;                      ///< the background cells before topology-aware splitting
  Eigen::Index background_cells_ = 0;
  int quadrature_strength_ = 0;
  std::shared_ptr<IntersectionStatistics> statistics_;
  VolumeMesh embedded_;
  std::vector<int> parent_tetrahedron_;  ///< FcmMesh::parent_tetrahedron of the mesh this was built on
  std::optional<PieceMesh> pieces_;      ///< topology-aware cells only
  int split_cells_ = 0;
  double topology_seconds_ = 0;
  FcmDiscretization fcm_;
  double material_volume_ = 0;
  std::vector<std::string> warnings_;
  double quadrature_seconds_ = 0;
};

// The kept background cells with their volume fractions and quadrature points, built as
// `run` builds them (the cut-cell rules included).
MeshPreview fcm_mesh_preview(const Scene& scene, const SceneGeometry& geometry, const MeshPreviewOptions& options) {
  if (!options.source.empty())
    throw InputError("--source " + options.source + ": fcm's mesh is its background grid (no --source)");
  const FcmMethod method(scene, geometry, nullptr);
  MeshPreview preview;
  preview.grid = method.volume_grid(Eigen::VectorXd::Zero(method.discretization().dof_count()));
  preview.facts = method.facts();
  preview.facts["elements"] = method.element_counts();
  preview.facts["quadrature_points"] = method.quadrature_points();
  preview.warnings = method.warnings();
  const nlohmann::json& cells = preview.facts["cells"];
  char text[512];
  std::snprintf(text, sizeof text,
                "fcm mesh of '%s': %s background grid, %d inside, %d cut, %d discarded, %d outside cells (%d split "
                "into pieces); %lld quadrature points (cut cells: %lld -> %lld)\n",
                scene.name.c_str(), preview.facts["background_resolution"].dump().c_str(), cells["inside"].get<int>(),
                cells["cut"].get<int>(), cells["discarded"].get<int>(), cells["outside"].get<int>(),
                cells["split"].get<int>(), preview.facts["quadrature_points"].get<long long>(),
                preview.facts["cut_cell_points"]["initial"].get<long long>(),
                preview.facts["cut_cell_points"]["final"].get<long long>());
  preview.summary = text;
  return preview;
}

}  // namespace

std::unique_ptr<MethodInstance> make_fcm_method(const Scene& scene, const SceneGeometry& geometry) {
  return std::make_unique<FcmMethod>(scene, geometry, nullptr);
}

const MethodDescription& fcm_method() {
  static const MethodDescription method{fcm_scene_block(), make_fcm_method,
                                        "finite cell method: Lagrange background grid, exact cut-cell quadrature",
                                        rebuild_on_handed_mesh<FcmMethod, FcmMesh>("fcm"), fcm_mesh_preview};
  return method;
}

}  // namespace altfem::fcm
