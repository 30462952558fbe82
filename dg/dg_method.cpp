#include "dg/dg_method.hpp"

#include <algorithm>
#include <chrono>
#include <limits>

#include "dg/definiteness_certificate.hpp"
#include "dg/dg_boundary_faces.hpp"
#include "dg/dg_discretization.hpp"
#include "dg/dg_integral_memory.hpp"
#include "dg/dg_linear_system.hpp"
#include "dg/dg_scene_block.hpp"
#include "dg/dg_transfer.hpp"
#include "dg/dg_volume_grid.hpp"
#include "dg/grid_coarse_levels.hpp"
#include "dg/monomial_basis_evaluator.hpp"
#include "dg/multigrid_coarse_space.hpp"
#include "dg/penalty_definiteness.hpp"
#include "dg/polyhedral_mesh_faces.hpp"
#include "dg/tabulated_dg.hpp"
#include "dg/vertex_coarse_space.hpp"
#include "dg/warped_dg_discretization.hpp"
#include "shared/common/error.hpp"
#include "shared/fem/cut_polyhedral_scene_mesh.hpp"
#include "shared/fem/lagrange_basis_evaluator.hpp"
#include "shared/fem/mesh_previews.hpp"
#include "shared/fem/refine_polyhedral_scene_mesh.hpp"
#include "shared/material/material.hpp"
#include "shared/simulation/embedded_surface.hpp"
#include "shared/simulation/mls_embedding.hpp"
#include "shared/simulation/scene_materials.hpp"
#include "shared/simulation/stitched_embedding.hpp"
#include "shared/solve/linear_solver.hpp"
#include "shared/solve/process_ranks.hpp"

namespace altfem::dg {

namespace {

// Doublings of η before giving up: 2²⁰ × the start is far beyond any useful penalty.
constexpr int max_doublings = 20;

// What an event hands the rebuild: the mesh, and what the build it replaces integrated and
// the penalty it reached, so that the cells and faces the event left alone keep their
// matrices (dg/dg_integral_memory.hpp).
struct DgMesh {
  PolyhedralSceneMesh mesh;
  std::shared_ptr<DgIntegralMemory> integrals;  ///< the rebuild moves what it takes out of them
  int doublings = 0;
};

class DgMethod final : public EmbeddedSurfaceMethod {
public:
  // On the mesh of the scene, or on a mesh an event hands it.
  DgMethod(const Scene& scene, const SceneGeometry& geometry, const DgMesh* handed)
      : spec_(dg_spec(scene)), materials_(scene) {
    PolyhedralSceneMesh built = handed ? handed->mesh : build_polyhedral_scene_mesh(spec_.mesh, geometry);
    mesh_ = std::move(built.sliced.mesh);
    surface_.surface = deformed_surface(built, geometry);
    surface_.common = built.surface.triangles.rows() == 0;  // else the mesh's own (deformed_surface)
    // Surface loads act on the boundary of the domain integrated: the mesh's.
    surface_.load_surface = std::move(built.load_surface);
    mesh_facts_ = std::move(built.facts);
    cell_levels_ = std::move(built.cell_levels);
    parent_cells_ = std::move(built.parent_cells);
    merged_parts_ = std::move(built.merged_parts);
    // Stitching interpolates with the converted mesh's basis (the block refuses it with a slice).
    if (built.converted) volume_mesh_ = std::move(*built.converted);
    std::vector<DgFace> faces = faces_with_conditions(mesh_, scene);
    if (spec_.strong_conditions) hold_strongly(scene, faces, mesh_.cell_count());
    for (const DirichletCondition& condition : scene.dirichlet) motions_.push_back(condition.motion);

    const auto start = std::chrono::steady_clock::now();
    cell_materials_ = cell_materials(scene, mesh_.cell_centroids);
    const DgMaterial& first = cell_materials_.materials.front();
    settings_ = {spec_.degree,
                 spec_.flux,
                 first.penalty,
                 first.lambda,
                 first.mu,
                 first.density,
                 boundary_factor(scene),
                 spec_.scaling,
                 first.tangential_fraction,
                 true,
                 spec_.rule_simplification};
    // PETSc sums the ranks' shares of K (docs/scaling.md), warped or not.
    settings_.share_stiffness = ranks::shares_matrices() && linear();
    // After an event, η starts where the run had doubled it to: it never drops during a
    // run, and the faces the event left alone keep their matrices.
    if (handed) double_penalty(handed->doublings);
    // Kept only where an event can rebuild on them (they hold every class's matrices).
    IntegralReuse reuse{handed ? handed->integrals : nullptr, events_rebuild(scene)};
    const std::vector<Polyhedron> cells = mesh_cells(mesh_);
    system_ = std::make_unique<DgLinearSystem>(cells, faces, settings_, cell_materials_, reuse);
    // The functions of a cell are contiguous and do not depend on the penalty.
    std::vector<std::vector<int>> element_dofs(mesh_.cell_count());
    for (int cell = 0; cell < mesh_.cell_count(); ++cell)
      for (int dof = 3 * system_->offset(cell); dof < 3 * system_->offset(cell + 1); ++dof)
        element_dofs[cell].push_back(dof);
    const bool iterative = is_iterative(scene.solver.linear);
    // Kaufmann et al. §8: "start with a low value and double it until K is positive
    // definite" (K of the linear material). Babuška–Zlámal is definite for any η > 0
    // (§9.1): its K is a sum of semidefinite volume terms and positive jump penalties, so
    // only interior penalty pays for the test.
    while (spec_.double_until_definite && linear() && spec_.flux == Flux::interior_penalty &&
           !definite(element_dofs, iterative)) {
      if (doublings_ >= max_doublings)
        throw NumericalError("dg: K is not positive definite after doubling the penalty " +
                             std::to_string(max_doublings) + " times");
      double_penalty(1);
      system_ = std::make_unique<DgLinearSystem>(cells, faces, settings_, cell_materials_, reuse);
    }
    auto external_force = [this](double time) { return weak_condition_load(time); };
    // Used only when the scene's solver/linear is iterative (the direct solvers ignore it).
    PreconditionerFactory preconditioner = preconditioner_factory(scene, element_dofs);
    if (spec_.warping) {
      // The consistency part of moving data is rotated with the boundary element (§6): the
      // discretization adds it; the load keeps the penalty's part.
      linear_ = std::make_unique<WarpedDgDiscretization>(
          *system_, settings_, density_integrals(), std::move(element_dofs),
          [this](double time) { return weak_condition_load(time, true); }, moving_data());
    } else if (linear()) {
      // The discretization keeps K; the system needs it no more.
      linear_ = std::make_unique<LinearDgDiscretization>(system_->take_stiffness(), system_->mass(),
                                                         density_integrals(), std::move(element_dofs), external_force,
                                                         strong_dofs(), system_->share_row_owners());
    }
    // PETSc's coarse level, for the one solver that uses it.
    CoarseSpace coarse_space = scene.solver.linear == LinearSolverKind::petsc && scene.solver.p_multigrid
                                   ? multigrid_coarse_space(mesh_, *system_)
                                   : CoarseSpace{};
    if (linear_) {
      linear_->use_preconditioner(std::move(preconditioner));
      linear_->use_coarse_space(std::move(coarse_space));
      discretization_ = linear_.get();
    } else {
      // Interior penalty lifts the data into F (dg/lifted_gradients.hpp); its load keeps the penalty's part.
      const bool lifted = spec_.flux == Flux::interior_penalty;
      tabulated_ = make_tabulated_dg(
          *system_, materials_.pointers(), [this, lifted](double time) { return weak_condition_load(time, lifted); },
          std::move(preconditioner), lifted ? moving_data() : ConditionTrajectory{}, strong_dofs(),
          std::move(coarse_space));
      discretization_ = tabulated_.discretization.get();
    }
    integration_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    surface_.evaluator = std::make_unique<MonomialBasisEvaluator>(mesh_, *system_);
    switch (spec_.embedding) {         // one of the three embeddings of §7
      case Embedding::element: break;  // EmbeddedSurface's own: each vertex in its element's basis
      case Embedding::stitched:
        surface_.make_embedding = [this](const EmbeddedSurface& surface) -> std::unique_ptr<PointEmbedding> {
          lagrange_ = std::make_unique<LagrangeBasisEvaluator>(volume_mesh_);
          return std::make_unique<StitchedEmbedding>(*surface.evaluator, volume_mesh_.nodes, *lagrange_,
                                                     embedding_points(surface.surface));
        };
        break;
      case Embedding::mls:
        surface_.make_embedding = [this](const EmbeddedSurface& surface) -> std::unique_ptr<PointEmbedding> {
          return std::make_unique<MlsEmbedding>(*surface.evaluator, mesh_.nodes, longest_edge_at_nodes(mesh_),
                                                embedding_points(surface.surface), MlsOptions{}, cells_at_nodes(mesh_),
                                                dynamic_cast<const MlsEmbedding*>(surface.embedding_before()));
        };
        break;
    }
  }

  const Discretization& discretization() const override { return *discretization_; }
  /// By degree, so that `compare` draws one series per order: {"k2_polyhedron": n}.
  nlohmann::json element_counts() const override {
    return {{"k" + std::to_string(spec_.degree) + "_polyhedron", mesh_.cell_count()}};
  }
  /// None for the linear material: every integral is exact (§5); else the volume rules'.
  long long quadrature_points() const override {
    return tabulated_.discretization ? tabulated_.discretization->elements().whole_point_count() : 0;
  }
  /// The exact integration and assembly (and the tabulation of a nonlinear material).
  double quadrature_seconds() const override { return integration_seconds_; }
  Eigen::VectorXd interpolate(const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& field) const override {
    return system_->interpolate(field);
  }
  UnstructuredGrid volume_grid(const Eigen::VectorXd& u) const override { return dg_volume_grid(*system_, u); }
  /// The monomials at polyhedron rules of strength 2k (+ added_strength), the strength
  /// at which a nonlinear material is tabulated (the linear one integrates exactly).
  std::optional<FieldQuadrature> field_quadrature(int added_strength) const override {
    const int strength = 2 * spec_.degree + added_strength;
    FieldQuadrature quadrature;
    quadrature.elements =
        std::make_shared<TabulatedElements>(tabulate_dg_cells(*system_, strength, &quadrature.points));
    quadrature.strength = strength;
    return quadrature;
  }
  /// The cells' exact volumes (polyhedron moments), without tabulating a rule.
  std::optional<double> volume() const override {
    double volume = 0;
    for (int cell = 0; cell < system_->cell_count(); ++cell) volume += system_->volume(cell);
    return volume;
  }
  std::shared_ptr<const MethodMesh> mesh() const override {
    return std::make_shared<MeshOf<DgMesh>>(handed_mesh(polyhedral_mesh()));
  }
  std::string cut_refusal() const override { return event_refusal("cut"); }
  std::shared_ptr<const MethodMesh> cut_mesh(const SceneEvent& cut, nlohmann::json& facts) const override {
    return std::make_shared<MeshOf<DgMesh>>(handed_mesh(cut_polyhedral_scene_mesh(polyhedral_mesh(), cut, facts)));
  }
  std::string refine_refusal(const RefineSpec& /*refine*/) const override { return event_refusal("refinement"); }
  std::shared_ptr<const MethodMesh> refine_mesh(const SceneEvent& refine, const Eigen::VectorXd& u,
                                                const PrescribedTraction& boundary,
                                                nlohmann::json& facts) const override {
    std::optional<PolyhedralSceneMesh> refined = refine_polyhedral_scene_mesh_by_stress(
        polyhedral_mesh(), refine, *field_quadrature(0)->elements, materials_, u, boundary, facts);
    if (!refined) return nullptr;
    return std::make_shared<MeshOf<DgMesh>>(handed_mesh(std::move(*refined)));
  }
  Eigen::MatrixXd transfer(const MethodInstance& previous, const Eigen::MatrixXd& fields) const override {
    const auto& before = dynamic_cast<const DgMethod&>(previous);
    return transfer_dg_field(*system_, *before.system_, before.basis_evaluator(), fields, parent_cells_, merged_parts_);
  }
  nlohmann::json facts() const override {
    nlohmann::json facts = mesh_facts_;
    const SimilarityStatistics& similarity = system_->similarity();
    facts.update({{"degree", spec_.degree},
                  {"flux", flux_names[static_cast<int>(spec_.flux)]},
                  {"penalty",
                   {{"convention", penalty_convention_names[static_cast<int>(spec_.convention)]},
                    {"value", spec_.penalty_value * (1 << doublings_)},
                    {"doublings", doublings_},
                    {"definiteness", definiteness_},
                    {"trace_ratio", trace_ratio_},
                    {"eta_pa", settings_.penalty},
                    {"scaling", penalty_scaling_names[static_cast<int>(spec_.scaling)]},
                    {"lame_split", spec_.lame_split}}},
                  {"smallest_cell_volume", smallest_cell_volume()},
                  // Element and face matrices computed once per class of translates
                  // (cell_similarity.hpp); after an event, the classes whose matrices were
                  // taken from the build before (dg_integral_memory.hpp).
                  {"similar_cells",
                   {{"cells", similarity.cells},
                    {"cell_classes", similarity.cell_classes},
                    {"faces", similarity.faces},
                    {"face_classes", similarity.face_classes},
                    {"remembered_cell_classes", similarity.remembered_cell_classes},
                    {"remembered_face_classes", similarity.remembered_face_classes}}},
                  {"warping", spec_.warping},
                  {"conditions", condition_imposition_names[spec_.strong_conditions ? 1 : 0]},
                  {"embedding", embedding_names[static_cast<int>(spec_.embedding)]}});
    facts.update(surface_.facts());
    return facts;
  }

private:
  // The mesh as built (for an event to change).
  PolyhedralSceneMesh polyhedral_mesh() const {
    PolyhedralSceneMesh mesh = handed_polyhedral_scene_mesh(mesh_, surface_.common ? nullptr : &surface_.surface,
                                                            surface_.load_surface, mesh_facts_, cell_levels_);
    if (volume_mesh_.nodes.rows() > 0) mesh.converted = volume_mesh_;
    return mesh;
  }
  DgMesh handed_mesh(PolyhedralSceneMesh mesh) const {
    return {std::move(mesh), system_->integral_memory(), doublings_};
  }
  // Whether K is definite: by the cell-by-cell certificate when it holds, which costs a small
  // eigenproblem per class of cells, else by the test that factorises K (it is sufficient
  // only, so the η reached is the same either way).
  bool definite(const std::vector<std::vector<int>>& element_dofs, bool iterative) {
    const DefinitenessCertificate certificate = certify_definiteness(*system_);
    trace_ratio_ = certificate.largest_ratio;
    if (certificate.certified) {
      definiteness_ = "certified";
      return true;
    }
    if (settings_.share_stiffness && ranks::distributed())
      throw NumericalError(
          "dg: the penalty's definiteness certificate does not hold (largest ratio " + std::to_string(trace_ratio_) +
          "), and its fallback factorises the whole K, which no rank holds when PETSc sums the ranks' shares: "
          "raise discretization.dg.penalty, or set penalty/double_until_definite to false");
    definiteness_ = iterative ? "pcg" : "factorisation";
    return positive_definite(*system_, element_dofs, iterative);
  }

  void double_penalty(int times) {
    doublings_ += times;
    settings_.penalty *= 1 << times;
    for (DgMaterial& material : cell_materials_.materials) material.penalty *= 1 << times;
  }
  std::string event_refusal(const std::string& event) const {
    return spec_.embedding == Embedding::stitched
               ? "its stitched embedding interpolates with the converted mesh, which a " + event +
                     " no longer matches (use embedding mls or element)"
               : "";
  }
  // The scene's preconditioner. The two-level and multilevel ones are refused (bad input)
  // when the vertex space would not be coarse: a cut cell of a detailed surface has far more
  // facet vertices than DOFs, and PᵀKP of the armadillo sliced at resolution 4 (35 cells,
  // 1,050 DOFs) exhausted 24 GB.
  PreconditionerFactory preconditioner_factory(const Scene& scene,
                                               const std::vector<std::vector<int>>& element_dofs) const {
    if (spec_.preconditioner == DgPreconditioner::block_jacobi) return block_jacobi_factory(element_dofs);
    VertexCoarseSpace space = vertex_coarse_space(mesh_, *system_);
    const auto coarse = static_cast<long>(space.prolongation.cols());
    const std::string name(dg_preconditioner_names[static_cast<int>(spec_.preconditioner)]);
    if (coarse > system_->dof_count())
      throw InputError(
          input_message(scene.file.string(), "/discretization/dg/preconditioner",
                        "'" + name + "' needs a coarse space smaller than the DG space, but the mesh's " +
                            std::to_string(space.nodes.size()) + " vertices give " + std::to_string(coarse) +
                            " coarse unknowns against " + std::to_string(system_->dof_count()) +
                            " DOFs (cut cells of a detailed surface have many facet vertices; use 'block_jacobi')"));
    if (spec_.preconditioner == DgPreconditioner::two_level)
      return two_level_factory(element_dofs, std::move(space.prolongation));
    std::vector<Eigen::SparseMatrix<double>> grid_levels = grid_coarse_levels(mesh_, *system_, space);
    return multilevel_factory(element_dofs, std::move(space.prolongation), std::move(grid_levels));
  }

  // The coefficients the strongly imposed conditions fix (none with weak conditions) and
  // the data's projection at every step, none while every motion is `fixed` (then 0).
  DirichletDofs strong_dofs() const {
    return {system_->constrained_dofs(),
            [this](double time) -> Eigen::VectorXd {
              if (!moving()) return Eigen::VectorXd::Zero(system_->constrained_dofs().size());
              return system_->constrained_values(
                  [&](int condition, const Eigen::Vector3d& x) { return motions_[condition].displacement(x, time); });
            },
            system_->constraint_holders()};
  }

  // Every material of the scene linear: the exact integration (else the tabulated one).
  bool linear() const {
    for (const Material* material : materials_.pointers())
      if (!material->is_linear()) return false;
    return true;
  }

  // The scene's materials as the system's: λ, μ, ρ and the convention's η of each
  // (docs/scene-schema.md, "Several materials"), each cell's by the centroid of its
  // corners (#cells × 3), as every method assigns them.
  DgCellMaterials cell_materials(const Scene& scene, const Eigen::MatrixX3d& centroids) const {
    DgCellMaterials result;
    for (size_t m = 0; m < scene.materials.size(); ++m) {
      const LameParameters lame = materials_.pointers()[m]->lame();
      const FacePenalty penalty = face_penalty(spec_, scene.materials[m].youngs_modulus, lame.lambda, lame.mu);
      result.materials.push_back(
          {lame.lambda, lame.mu, scene.materials[m].density, penalty.eta, penalty.tangential_fraction});
    }
    result.ids = materials_.ids_of(centroids);
    return result;
  }

  // c_f of Dirichlet faces: the convention's, the same for every material.
  double boundary_factor(const Scene& scene) const {
    const LameParameters lame = materials_.pointers().front()->lame();
    return face_penalty(spec_, scene.material.youngs_modulus, lame.lambda, lame.mu).boundary_factor;
  }

  // The cells' smallest volume: with a slice, over slicing.cell_size³ the smallest piece
  // the sliver merging kept (the penalty grows like 1/ℓ(K) on it).
  double smallest_cell_volume() const {
    double smallest = std::numeric_limits<double>::infinity();
    for (int cell = 0; cell < system_->cell_count(); ++cell) smallest = std::min(smallest, system_->volume(cell));
    return smallest;
  }

  // ∫ ρ φ_a dV of every function, with its cell's density.
  Eigen::VectorXd density_integrals() const {
    Eigen::VectorXd integrals = system_->function_integrals();
    for (int cell = 0; cell < mesh_.cell_count(); ++cell)
      integrals.segment(system_->offset(cell), system_->offset(cell + 1) - system_->offset(cell)) *=
          system_->material(cell).density;
    return integrals;
  }

  // The conditions' data g(condition, x, t); empty while every motion is `fixed`.
  ConditionTrajectory moving_data() const {
    if (!moving()) return {};
    return [this](int condition, const Eigen::Vector3d& x, double time) {
      return motions_[condition].displacement(x, time);
    };
  }

  bool moving() const {
    for (const Motion& motion : motions_)
      if (motion.kind != MotionKind::fixed) return true;
    return false;
  }

  // The data part of the weakly imposed conditions at a time (§4.2), its penalty's part
  // alone with `penalty_only`: zero while every motion is `fixed`.
  Eigen::VectorXd weak_condition_load(double time, bool penalty_only = false) const {
    if (!moving()) return Eigen::VectorXd::Zero(system_->dof_count());
    return system_->dirichlet_load(
        [&](int condition, const Eigen::Vector3d& x) { return motions_[condition].displacement(x, time); },
        penalty_only);
  }

  DgSpec spec_;
  DgSettings settings_;  // with the first material's λ, μ, ρ, η
  DgCellMaterials cell_materials_;
  int doublings_ = 0;
  // What decided that K is definite ("certified", "factorisation", "pcg"; "untested" when
  // nothing had to), and the certificate's largest eigenvalue ratio (< 1 certifies).
  std::string definiteness_ = "untested";
  double trace_ratio_ = 0;
  VolumeMesh volume_mesh_;  // the mesh converted into mesh_
  PolyhedralMesh mesh_;
  nlohmann::json mesh_facts_;      // its source (build_polyhedral_scene_mesh)
  std::vector<int> cell_levels_;   // per cell, the refinements it came through (empty: none)
  std::vector<int> parent_cells_;  // per cell, the cell of the build before holding it (empty: not an event's)
  std::vector<std::vector<ParentPart>> merged_parts_;  // per cell merged from pieces of several, those pieces
  std::vector<Motion> motions_;                        // per Dirichlet condition
  std::unique_ptr<DgLinearSystem> system_;
  SceneMaterials materials_;
  std::unique_ptr<LinearDgDiscretization> linear_;  // the linear material, warped or not
  TabulatedDg tabulated_;                           // any other
  const Discretization* discretization_ = nullptr;
  std::unique_ptr<LagrangeBasisEvaluator> lagrange_;  // over volume_mesh_: the stitched embedding's interpolation
  double integration_seconds_ = 0;
};

}  // namespace

std::unique_ptr<MethodInstance> make_dg_method(const Scene& scene, const SceneGeometry& geometry) {
  return std::make_unique<DgMethod>(scene, geometry, nullptr);
}

const MethodDescription& dg_method() {
  static const MethodDescription method{
      dg_scene_block(), make_dg_method, "interior-penalty / Babuska-Zlamal DG, monomials k = 1-3 on polyhedra",
      rebuild_on_handed_mesh<DgMethod, DgMesh>("dg"),
      [](const Scene& scene, const SceneGeometry& geometry, const MeshPreviewOptions& options) {
        return polyhedral_mesh_preview("dg", scene, geometry, dg_spec(scene).mesh, options);
      }};
  return method;
}

}  // namespace altfem::dg
