#include "fcm/fcm_method.hpp"

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
    return std::make_shared<MeshOf<FcmMesh>>(FcmMesh{background_, resolution_, embedded_});
  }
  Eigen::MatrixXd transfer(const MethodInstance& previous, const Eigen::MatrixXd& fields) const override {
    const auto& before = dynamic_cast<const FcmMethod&>(previous);
    return transfer_to_nodes(fcm_.mesh.nodes, before.fcm_.mesh.nodes, before.basis_evaluator(), fields);
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
  SceneMaterials materials_;
  std::optional<Eigen::Vector3i> resolution_;  ///< nullopt: a background mesh file
  VolumeMesh background_;                      ///< the background cells before topology-aware splitting
  Eigen::Index background_cells_ = 0;
  int quadrature_strength_ = 0;
  std::shared_ptr<IntersectionStatistics> statistics_;
  VolumeMesh embedded_;
  std::optional<PieceMesh> pieces_;  ///< topology-aware cells only
  int split_cells_ = 0;
  double topology_seconds_ = 0;
  FcmDiscretization fcm_;
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
