#include "fcm/fcm_method.hpp"

#include <cstdio>
#include <optional>

#include "fcm/embedded_mesh.hpp"
#include "fcm/fcm_scene_block.hpp"
#include "shared/common/error.hpp"
#include "shared/cut_cells/embedded_cut_cells.hpp"
#include "shared/fem/refine_hexahedral_grid.hpp"
#include "shared/mesh/boundary_surface.hpp"
#include "shared/mesh/hexahedral_forest.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "shared/simulation/basis_embedding.hpp"
#include "shared/simulation/cell_stresses.hpp"
#include "shared/simulation/embedded_surface.hpp"
#include "shared/simulation/nodal_basis.hpp"
#include "shared/simulation/scene_materials.hpp"

namespace altfem::fcm {

namespace {

// What the method is built on: the background cells (§3.2) and the object as
// embedded tetrahedra (§4.5), cut or not. A generated hexahedral grid is kept as a forest
// too, which a refine event splits (issue #34; the paper does not refine).
struct FcmMesh {
  VolumeMesh background;
  std::optional<Eigen::Vector3i> resolution;  ///< nullopt: a background mesh file
  EmbeddedTetrahedra embedded;
  std::optional<HexahedralForest> forest;
  /// The forest's hanging nodes, last in `background` (none: free_nodes is every node).
  int free_nodes = 0;
  HangingNodeSources hanging;
  /// The cell rules of the build an event started from, for the cells it left alone.
  std::shared_ptr<const CellRuleMemory> rules;
  /// Its tetrahedra's clips by its cells, for the tetrahedra and cells it left alone.
  std::shared_ptr<const ClippedTetrahedronMemory> clips;
};

// The stress per leaf of `forest` that marks it: of its kept cells (pieces) the one whose
// largest absolute principal stress is largest; zero where no cell is kept.
std::vector<Eigen::Matrix3d> leaf_stresses(const HexahedralForest& forest, const std::vector<int>& leaf_of_kept,
                                           const std::vector<Eigen::Matrix3d>& kept_stresses) {
  std::vector<Eigen::Matrix3d> stresses(static_cast<std::size_t>(forest.leaf_count()), Eigen::Matrix3d::Zero());
  const auto largest = [](const Eigen::Matrix3d& stress) { return largest_principal_stress(stress).value; };
  for (std::size_t cell = 0; cell < leaf_of_kept.size(); ++cell) {
    Eigen::Matrix3d& stress = stresses[leaf_of_kept[cell]];
    if (largest(kept_stresses[cell]) > largest(stress)) stress = kept_stresses[cell];
  }
  return stresses;
}

CutCellSettings cut_cell_settings(const FcmSpec& spec) {
  return {spec.options, spec.simplifier, spec.simplification_tolerance, spec.topology_aware};
}

class FcmMethod final : public EmbeddedSurfaceMethod {
public:
  // On the meshes of the scene, or on meshes an event hands it.
  FcmMethod(const Scene& scene, const SceneGeometry& geometry, const FcmMesh* handed) : materials_(scene) {
    const FcmSpec spec = fcm_spec(scene);
    for (const SceneEvent& event : scene.events) scene_cuts_ = scene_cuts_ || event.kind == EventKind::cut;
    FcmMesh meshes;
    if (handed) {
      meshes = *handed;
    } else {
      // The background grid over the geometry's bounds, or the user's mesh (§3.2).
      BackgroundMesh generated = background_mesh(spec, geometry.bounds);
      meshes.background = std::move(generated.mesh);
      meshes.resolution = generated.resolution;
      if (generated.resolution && element_shape(spec.cell) == ElementShape::hexahedron) {
        const Eigen::AlignedBox3d box(meshes.background.nodes.colwise().minCoeff().transpose(),
                                      meshes.background.nodes.colwise().maxCoeff().transpose());
        meshes.forest = grid_forest(box, *generated.resolution, spec.cell);
      }
      // The object as tetrahedra (§4.5): the scene's tet mesh, or Mesh_3 of its surface
      // or shape at the same default size as fem's, so both deform the same surface.
      const double embedded_size = spec.embedded_cell_size.value_or(geometry.bounds.diagonal().norm() / 15.0);
      meshes.embedded.material.mesh = embedded_tetrahedra(geometry, embedded_size, scene.file.string());
    }
    resolution_ = meshes.resolution;
    forest_ = std::move(meshes.forest);
    std::optional<RefinedBackground> refined;
    if (!meshes.hanging.empty())
      refined = RefinedBackground{meshes.free_nodes, std::move(meshes.hanging),
                                  forest_face_contacts(forest_interior_faces(*forest_))};
    cells_ = std::make_unique<EmbeddedCutCells>(
        meshes.background, std::move(meshes.embedded), cut_cell_settings(spec), materials_, scene.dirichlet,
        scene.file.string(),
        CutCellRebuild{refined ? &*refined : nullptr, meshes.rules, meshes.clips, events_rebuild(scene)});
    if (refined) {
      grid_free_nodes_ = refined->free_nodes;
      grid_hanging_ = std::move(refined->sources);
    }
    // The surface every method deforms: the scene's own, else the boundary of the
    // embedded mesh. Points in discarded cells take the nearest kept cell's basis (§5.3).
    // Surface loads act on the boundary of the domain integrated: the embedded tetrahedra's,
    // made only where a traction or the surface needs it (after each cut of a pencil's tip,
    // a sixth of its rebuild).
    if (!scene.tractions.empty() || !geometry.common_surface())
      surface_.load_surface = boundary_surface(cells_->embedded().mesh()).surface;
    surface_.surface = geometry.common_surface() ? *geometry.common_surface() : surface_.load_surface;
    surface_.common = geometry.common_surface() != nullptr;
    surface_.evaluator = cells_->basis_evaluator();
  }

  const Discretization& discretization() const override { return *kept_cells().discretization; }
  nlohmann::json element_counts() const override {
    return {{std::string(element_name(kept_cells().mesh.element_type)), kept_cells().mesh.cells.rows()}};
  }
  long long quadrature_points() const override { return kept_cells().discretization->elements().whole_point_count(); }
  double quadrature_seconds() const override { return cells_->seconds(); }
  UnstructuredGrid volume_grid(const Eigen::VectorXd& displacement) const override {
    UnstructuredGrid grid = cells_->volume_grid(displacement);
    // Each cell's refinement level, to colour a refined grid by in ParaView.
    if (forest_) {
      Eigen::VectorXd levels(kept_cells().mesh.cells.rows());
      const std::vector<int> leaves = cells_->background_cell_of_kept();
      for (Eigen::Index cell = 0; cell < levels.size(); ++cell) levels[cell] = forest_->levels[leaves[cell]];
      grid.cell_data.emplace_back("level", levels);
    }
    return grid;
  }
  Eigen::VectorXd interpolate(const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& field) const override {
    return interpolate_at_nodes(free_nodes(), field);
  }
  std::vector<std::string> warnings() const override { return cells_->warnings(); }
  std::shared_ptr<const MethodMesh> mesh() const override {
    return std::make_shared<MeshOf<FcmMesh>>(FcmMesh{cells_->background(),
                                                     resolution_,
                                                     {cells_->embedded().material, {}},
                                                     forest_,
                                                     grid_free_nodes_,
                                                     grid_hanging_,
                                                     cells_->rule_memory(),
                                                     cells_->clip_memory()});
  }
  std::string refine_refusal(const RefineSpec& refine) const override {
    if (!forest_)
      return "it refines generated hexahedral grids only (discretization.fcm: a hex8, hex20 or hex27 `cell`, no "
             "`background` file)";
    return grid_refine_refusal(refine, scene_cuts_);
  }
  /// The grid's leaves whose stress the event marks split 1→8, the forest balanced 2:1
  /// (refine_hexahedral_grid); the embedded tetrahedra stay as they are, and only the
  /// refined cells get new rules.
  std::shared_ptr<const MethodMesh> refine_mesh(const SceneEvent& refine, const Eigen::VectorXd& displacement,
                                                const PrescribedTraction& /*boundary*/,
                                                nlohmann::json& facts) const override {
    const std::vector<Eigen::Matrix3d> stresses =
        leaf_stresses(*forest_, cells_->background_cell_of_kept(),
                      mean_cell_stresses(kept_cells().discretization->elements(), materials_.pointers(), displacement));
    // The body's boundary crosses the cut cells, not the grid's box: no boundary residual.
    std::optional<RefinedGrid> refined = refine_hexahedral_grid(*forest_, refine.refine, stresses, nullptr, facts);
    if (!refined) return nullptr;
    return std::make_shared<MeshOf<FcmMesh>>(FcmMesh{std::move(refined->mesh.mesh),
                                                     resolution_,
                                                     {cells_->embedded().material, {}},
                                                     std::move(refined->forest),
                                                     refined->mesh.constraints.free_nodes,
                                                     std::move(refined->mesh.sources),
                                                     cells_->rule_memory(),
                                                     cells_->clip_memory()});
  }
  /// The material's volume Σ vol(K ∩ Ω) over the kept cells (EmbeddedCutCells).
  std::optional<double> volume() const override { return cells_->material_volume(); }
  std::string cut_refusal() const override { return cells_->cut_refusal(); }
  std::shared_ptr<const MethodMesh> cut_mesh(const SceneEvent& cut, nlohmann::json& facts) const override {
    return std::make_shared<MeshOf<FcmMesh>>(FcmMesh{cells_->background(), resolution_, cells_->cut(cut.blade, facts),
                                                     forest_, grid_free_nodes_, grid_hanging_, cells_->rule_memory(),
                                                     cells_->clip_memory()});
  }
  /// Nodal values at the nodes (transfer_to_nodes); after a cut a node copy takes the
  /// values of the copy its material came from, which a position cannot tell apart.
  Eigen::MatrixXd transfer(const MethodInstance& previous, const Eigen::MatrixXd& fields) const override {
    const auto& before = dynamic_cast<const FcmMethod&>(previous);
    return cells_->transfer(*before.cells_, before.basis_evaluator(), fields);
  }
  /// The stiffness rules at any requested strength: cut cells' rules are simplified to
  /// match the moments up to that strength only (§4), so no stronger rule is at hand. The
  /// stabilising points (§5.3, weights × `stabilization`) are included.
  std::optional<FieldQuadrature> field_quadrature(int /*added_strength*/) const override {
    return nodal_field_quadrature(borrowed(kept_cells().discretization->elements()), free_nodes(),
                                  cells_->quadrature_strength());
  }
  nlohmann::json facts() const override {
    nlohmann::json facts = surface_.facts();
    facts.update(cells_->facts());
    if (forest_) facts["hanging_nodes"] = kept_cells().constraints.hanging_nodes();
    facts.update(
        {{"background_cells", cells_->background().cells.rows()},
         {"background_resolution", resolution_ ? nlohmann::json{resolution_->x(), resolution_->y(), resolution_->z()}
                                               : nlohmann::json("file")}});
    return facts;
  }

private:
  const FcmDiscretization& kept_cells() const { return cells_->discretization(); }
  // The kept nodes that carry the basis (#free nodes × 3): all but the hanging ones.
  Eigen::MatrixXd free_nodes() const { return kept_cells().mesh.nodes.topRows(kept_cells().constraints.free_nodes); }

  SceneMaterials materials_;
  std::optional<Eigen::Vector3i> resolution_;  ///< nullopt: a background mesh file
  std::optional<HexahedralForest> forest_;     ///< a generated hexahedral grid, refined or not
  int grid_free_nodes_ = 0;                    ///< its nodes from here on hang,
  HangingNodeSources grid_hanging_;            ///< from these
  bool scene_cuts_ = false;
  std::unique_ptr<EmbeddedCutCells> cells_;
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
