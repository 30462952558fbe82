#include "polyhedral/harmonic_method.hpp"

#include <chrono>
#include <string>
#include <vector>

#include "polyhedral/cut_piece_fits.hpp"
#include "polyhedral/harmonic_basis_cache.hpp"
#include "polyhedral/harmonic_basis_evaluator.hpp"
#include "polyhedral/harmonic_element_bases.hpp"
#include "polyhedral/harmonic_scene_block.hpp"
#include "shared/assembly/tabulated_discretization.hpp"
#include "shared/assembly/warped_linear_discretization.hpp"
#include "shared/common/error.hpp"
#include "shared/fem/cut_polyhedral_scene_mesh.hpp"
#include "shared/fem/mesh_previews.hpp"
#include "shared/fem/nodal_dirichlet.hpp"
#include "shared/fem/refine_polyhedral_scene_mesh.hpp"
#include "shared/io/polyhedral_grid.hpp"
#include "shared/mesh/flat_cells.hpp"
#include "shared/simulation/embedded_surface.hpp"
#include "shared/simulation/nodal_basis.hpp"
#include "shared/simulation/scene_materials.hpp"

namespace altfem::harmonic {

namespace {

// What an event hands the rebuild: the mesh, and the MFS bases and stiffness tabulation of
// the build it replaces, which the cells it left alone keep (harmonic_basis_memory.hpp,
// EarlierTabulation: valid while that build lives, as it does through the rebuild).
struct HarmonicMesh {
  PolyhedralSceneMesh mesh;
  std::shared_ptr<const HarmonicBasisMemory> bases;
  EarlierTabulation tabulation{};
};

class HarmonicMethod final : public EmbeddedSurfaceMethod {
public:
  // On the mesh of the scene, or on a mesh an event hands it.
  HarmonicMethod(const Scene& scene, const SceneGeometry& geometry, const HarmonicMesh* handed)
      : materials_(scene), spec_(harmonic_spec(scene)) {
    // fem's tet or hex mesh cell by cell, or the geometry sliced: its grid's hexahedra
    // keep the trilinear basis with `basis: auto`, only cut cells pay for MFS.
    PolyhedralSceneMesh built = handed ? handed->mesh : build_polyhedral_scene_mesh(spec_.mesh, geometry);
    mesh_ = std::move(built.sliced.mesh);
    surface_.surface = deformed_surface(built, geometry);
    surface_.common = built.surface.triangles.rows() == 0;  // else the mesh's own (deformed_surface)
    // Surface loads act on the boundary of the domain integrated: the mesh's.
    surface_.load_surface = std::move(built.load_surface);
    mesh_facts_ = std::move(built.facts);
    node_sources_ = std::move(built.node_sources);
    cell_levels_ = std::move(built.cell_levels);
    const auto start = std::chrono::steady_clock::now();
    if (spec_.cache.empty()) {
      // Kept only where an event can rebuild on them. Every shape the run has met: the
      // memory of the build before, and this one's.
      if (events_rebuild(scene))
        basis_memory_ = handed && handed->bases ? std::make_shared<HarmonicBasisMemory>(*handed->bases)
                                                : std::make_shared<HarmonicBasisMemory>(spec_.mfs);
      bases_ = std::make_unique<HarmonicElementBases>(mesh_, spec_.basis, spec_.mfs,
                                                      handed ? handed->bases.get() : nullptr, basis_memory_.get());
    } else {
      bool reused = false;
      try {
        bases_ = std::make_unique<HarmonicElementBases>(
            cached_harmonic_bases(mesh_, spec_.basis, spec_.mfs, spec_.cache, &reused));
      } catch (const NumericalError&) {
        throw;
      } catch (const std::runtime_error& error) {  // the cache file cannot be written
        throw InputError(input_message(scene.file.string(), "/discretization/harmonic/cache", error.what()));
      }
      basis_cache_ = reused ? "reused" : "written";
    }
    DiscretizationParts parts;
    quadrature_order_ = spec_.quadrature_order;
    quadrature_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // Over several ranks each tabulates only its cells (TabulatedDiscretization calls this
    // while it is built, below); the tabulation's seconds count with the bases'.
    const EarlierTabulation earlier = handed ? handed->tabulation : EarlierTabulation{};
    parts.tabulate = [this, order = spec_.quadrature_order, quadrature = spec_.quadrature, earlier,
                      materials = materials_.ids_of(mesh_.cell_centroids)](const TabulatedHere& here,
                                                                           const TabulatedElements* listed) {
      const auto begin = std::chrono::steady_clock::now();
      TabulatedElements elements = bases_->tabulate(order, quadrature, materials, here, listed,
                                                    earlier.bases ? &earlier : nullptr, &copied_tabulations_);
      quadrature_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
      return elements;
    };
    parts.materials = materials_.pointers();
    // The basis is nodal (N_i(x_j) = δ_ij up to the fit), so conditions are strong on
    // the nodes, as in fem; the lumped mass suits its partition of unity.
    parts.dirichlet = nodal_dirichlet(mesh_.nodes, scene.dirichlet, scene.file.string(), "the harmonic mesh");
    parts.explicit_mass = ExplicitMassKind::lumped;
    if (spec_.warping) {
      check_warped_materials(scene);
      auto warped = std::make_unique<WarpedLinearDiscretization>(std::move(parts), mesh_.nodes);
      elements_ = &warped->elements();
      discretization_ = std::move(warped);
    } else {
      auto linear = std::make_unique<TabulatedDiscretization>(std::move(parts));
      elements_ = &linear->elements();
      discretization_ = std::move(linear);
    }
    for (int cell = 0; cell < bases_->cell_count(); ++cell)
      if (bases_->mfs_basis(cell)) mfs_quadrature_points_ += elements_->whole_point_count(cell);
    surface_.evaluator = std::make_unique<HarmonicBasisEvaluator>(mesh_, *bases_);
    // Trilinear and harmonic bases are complete to degree 1 only (Martin et al. 2008 §4).
    if (auto warning = flat_cell_locking_warning(
            mesh_, "harmonic",
            "use fem (tet10, hex20), fcm (hex20) or dg (degree 2), or cells as thin as the geometry"))
      warnings_.push_back(std::move(*warning));
  }

  const Discretization& discretization() const override { return *discretization_; }
  /// The stiffness tabulation, or every cell re-tabulated at the stronger rule; the
  /// points from the basis' linear precision (exact on plain cells, to the MFS fit elsewhere).
  /// The stronger rule (errors, energies) is the full cone rule whatever `rule` says, so
  /// the solutions of every rule kind are measured alike and exactly to its strength.
  std::optional<FieldQuadrature> field_quadrature(int added_strength) const override {
    if (added_strength == 0) return nodal_field_quadrature(borrowed(*elements_), mesh_.nodes, quadrature_order_);
    const int strength = quadrature_order_ + added_strength;
    const HarmonicQuadrature full_cone{.kind = HarmonicRuleKind::cone, .simplifier = std::nullopt};
    return nodal_field_quadrature(std::make_shared<TabulatedElements>(bases_->tabulate(strength, full_cone)),
                                  mesh_.nodes, strength);
  }
  nlohmann::json element_counts() const override {
    long long tet4 = 0, hex8 = 0, mfs = 0;
    for (int cell = 0; cell < bases_->cell_count(); ++cell) {
      const auto type = bases_->plain_type(cell);
      (type ? (*type == ElementType::tet4 ? tet4 : hex8) : mfs) += 1;
    }
    // Written as polyhedra (VTK 42) whatever their basis: not the Lagrange names.
    nlohmann::json counts = nlohmann::json::object();
    if (tet4 > 0) counts["linear_tetrahedron"] = tet4;
    if (hex8 > 0) counts["trilinear_hexahedron"] = hex8;
    if (mfs > 0) counts["mfs_polyhedron"] = mfs;
    return counts;
  }
  long long quadrature_points() const override { return elements_->whole_point_count(); }
  double quadrature_seconds() const override { return quadrature_seconds_; }
  UnstructuredGrid volume_grid(const Eigen::VectorXd& displacement) const override {
    UnstructuredGrid grid = grid_from_polyhedral_mesh(mesh_);
    add_nodal_displacement(grid, displacement);
    return grid;
  }
  Eigen::VectorXd interpolate(const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& field) const override {
    return interpolate_at_nodes(mesh_.nodes, field);
  }
  std::shared_ptr<const MethodMesh> mesh() const override { return handed_mesh(polyhedral_mesh()); }
  std::string cut_refusal() const override { return ""; }
  std::shared_ptr<const MethodMesh> cut_mesh(const SceneEvent& cut, nlohmann::json& facts) const override {
    // Each new cell's fit is checked before it becomes an element; the fits that pass go
    // into the memory the build on the cut mesh reads (a fresh one without it: the cache).
    HarmonicBasisMemory scratch(spec_.mfs);
    HarmonicBasisMemory& memory = basis_memory_ ? *basis_memory_ : scratch;
    double fitting_seconds = 0;
    const RefusedCells refused = [&](const PolyhedralMesh& pieces, const std::vector<int>& candidates) {
      const auto start = std::chrono::steady_clock::now();
      std::vector<bool> fails =
          cells_whose_fit_fails(pieces, candidates, spec_.basis, spec_.mfs, spec_.cut_piece_residual, memory);
      fitting_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      return fails;
    };
    PolyhedralSceneMesh cut_mesh = cut_polyhedral_scene_mesh(polyhedral_mesh(), cut, facts, refused);
    return handed_mesh(std::move(cut_mesh), fitting_seconds);
  }
  std::string refine_refusal(const RefineSpec& /*refine*/) const override { return ""; }
  std::shared_ptr<const MethodMesh> refine_mesh(const SceneEvent& refine, const Eigen::VectorXd& u,
                                                const PrescribedTraction& boundary,
                                                nlohmann::json& facts) const override {
    std::optional<PolyhedralSceneMesh> refined =
        refine_polyhedral_scene_mesh_by_stress(polyhedral_mesh(), refine, *elements_, materials_, u, boundary, facts);
    if (!refined) return nullptr;
    return handed_mesh(std::move(*refined));
  }
  Eigen::MatrixXd transfer(const MethodInstance& previous, const Eigen::MatrixXd& fields) const override {
    const auto& before = dynamic_cast<const HarmonicMethod&>(previous);
    if (node_sources_.empty())
      return transfer_to_nodes(mesh_.nodes, before.mesh_.nodes, before.basis_evaluator(), fields);
    // Cut from `before`'s mesh: each node from its sources, linear along the cut edge
    // (Martin et al. 2008 §4: a harmonic basis is linear on the edges).
    Eigen::MatrixXd result(3 * mesh_.nodes.rows(), fields.cols());
    for (Eigen::Index node = 0; node < mesh_.nodes.rows(); ++node) {
      const NodeSource& source = node_sources_[node];
      result.middleRows<3>(3 * node) = (1 - source.weight) * fields.middleRows<3>(3 * Eigen::Index{source.first}) +
                                       source.weight * fields.middleRows<3>(3 * Eigen::Index{source.second});
    }
    return result;
  }
  std::vector<std::string> warnings() const override { return warnings_; }
  nlohmann::json facts() const override {
    nlohmann::json facts = surface_.facts();
    facts.update(mesh_facts_);
    facts["max_mfs_boundary_residual"] = bases_->max_boundary_residual();
    facts["mfs_quadrature_points"] = mfs_quadrature_points_;
    if (!basis_cache_.empty()) facts["harmonic_basis_cache"] = basis_cache_;
    // After an event, the MFS cells it left alone, whose bases were not fitted again.
    facts["remembered_mfs_bases"] = bases_->remembered_bases();
    // MFS cells that took the fit of a translate or scaled copy of theirs (one fit per shape).
    facts["moved_mfs_bases"] = bases_->moved_bases();
    // After an event, the MFS cells it left alone whose points were copied, not evaluated again.
    facts["copied_mfs_tabulations"] = copied_tabulations_;
    return facts;
  }

private:
  // The mesh as built (for an event to change).
  PolyhedralSceneMesh polyhedral_mesh() const {
    return handed_polyhedral_scene_mesh(mesh_, surface_.common ? nullptr : &surface_.surface, surface_.load_surface,
                                        mesh_facts_, cell_levels_);
  }
  std::shared_ptr<const MethodMesh> handed_mesh(PolyhedralSceneMesh mesh, double integration_seconds = 0) const {
    auto handed = std::make_shared<MeshOf<HarmonicMesh>>(
        HarmonicMesh{std::move(mesh), basis_memory_, {bases_.get(), elements_, quadrature_order_}});
    handed->integration_seconds = integration_seconds;
    return handed;
  }

  // Martin et al. 2008 §6 warp the linear stiffness; the nonlinear models are already
  // rotation-invariant (and corotated_linear is the warping's own continuum model).
  static void check_warped_materials(const Scene& scene) {
    for (const MaterialSpec& material : scene.materials)
      if (material.model != "linear")
        throw InputError(input_message(scene.file.string(), "/discretization/harmonic/warping",
                                       "stiffness warping corotates the 'linear' material, but " + material.pointer +
                                           "/model is '" + material.model + "' (use warping false)"));
  }

  SceneMaterials materials_;
  HarmonicSpec spec_;  // the resolved block
  PolyhedralMesh mesh_;
  nlohmann::json mesh_facts_;             // its source (build_polyhedral_scene_mesh)
  std::vector<NodeSource> node_sources_;  // how mesh_ was cut from the previous instance's (empty: not cut)
  std::vector<int> cell_levels_;          // per cell, the refinements it came through (empty: none)
  std::unique_ptr<HarmonicElementBases> bases_;
  std::shared_ptr<HarmonicBasisMemory> basis_memory_;  // every MFS shape met, where events rebuild
  std::unique_ptr<Discretization> discretization_;     // linear, or warped (§6)
  const TabulatedElements* elements_ = nullptr;        // its stiffness tabulation
  double quadrature_seconds_ = 0;
  std::string basis_cache_;  // "reused" or "written" with /discretization/harmonic/cache, else empty
  int quadrature_order_ = 0;
  long long mfs_quadrature_points_ = 0;  // the stiffness rule's points on MFS cells
  int copied_tabulations_ = 0;           // MFS cells whose points came from the build before
  std::vector<std::string> warnings_;
};

}  // namespace

std::unique_ptr<MethodInstance> make_harmonic_method(const Scene& scene, const SceneGeometry& geometry) {
  return std::make_unique<HarmonicMethod>(scene, geometry, nullptr);
}

const MethodDescription& harmonic_method() {
  static const MethodDescription method{
      harmonic_scene_block(), make_harmonic_method, "harmonic-basis polyhedral FEM (MFS bases, Martin et al. 2008)",
      rebuild_on_handed_mesh<HarmonicMethod, HarmonicMesh>("harmonic"),
      [](const Scene& scene, const SceneGeometry& geometry, const MeshPreviewOptions& options) {
        return polyhedral_mesh_preview("harmonic", scene, geometry, harmonic_spec(scene).mesh, options);
      }};
  return method;
}

}  // namespace altfem::harmonic
