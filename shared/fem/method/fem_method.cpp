#include "shared/fem/method/fem_method.hpp"

#include <chrono>

#include "shared/fem/constrain_lagrange_elements.hpp"
#include "shared/fem/fem_mesh.hpp"
#include "shared/fem/lagrange_basis_evaluator.hpp"
#include "shared/fem/lagrange_discretization.hpp"
#include "shared/fem/lagrange_surface_lift.hpp"
#include "shared/fem/mesh_previews.hpp"
#include "shared/fem/method/cut_fem_method.hpp"
#include "shared/fem/refine_hexahedral_grid.hpp"
#include "shared/fem/tabulate_lagrange.hpp"
#include "shared/mesh/boundary_surface.hpp"
#include "shared/simulation/basis_embedding.hpp"
#include "shared/simulation/cell_stresses.hpp"
#include "shared/simulation/embedded_surface.hpp"
#include "shared/simulation/nodal_basis.hpp"
#include "shared/simulation/scene_materials.hpp"

namespace altfem {

namespace {

class FemMethod final : public EmbeddedSurfaceMethod {
public:
  // On the mesh of the scene (build_fem_mesh), or on a mesh an event hands it. A hexahedral
  // grid is kept as a forest too, which a refine event splits.
  FemMethod(const Scene& scene, const SceneGeometry& geometry, const FemMesh* handed) : materials_(scene) {
    const FemSpec fem = fem_spec(scene);
    quadrature_order_ = fem.quadrature_order;
    for (const SceneEvent& event : scene.events) {
      scene_cuts_ = scene_cuts_ || event.kind == EventKind::cut;
      scene_refines_ = scene_refines_ || event.kind == EventKind::refine;
    }
    if (scene_cuts_) failure_hint_ = fem_cut_failure_hint(fem.cut_stabilization);
    if (handed) {
      mesh_ = handed->elements;
      forest_ = handed->forest;
      constraints_ = handed->constraints;
    } else {
      mesh_ = build_fem_mesh(fem, geometry);
      if (fem.mesh == FemMeshKind::grid && element_shape(fem.element) == ElementShape::hexahedron) {
        forest_ = grid_forest(geometry.bounds, fem.resolution, fem.element);
        const std::vector<bool> inside = grid_cells_in_shape(fem, geometry);
        if (!inside.empty()) keep_leaves(*forest_, inside);
      }
    }
    if (constraints_.empty()) constraints_.free_nodes = static_cast<int>(mesh_.nodes.rows());  // none hangs
    const auto start = std::chrono::steady_clock::now();
    discretization_ =
        make_lagrange_discretization(mesh_, materials_.pointers(), materials_.ids_of(corner_centroids(mesh_)),
                                     scene.dirichlet, fem.quadrature_order, scene.file.string(), &constraints_);
    quadrature_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // The surface every method deforms (SceneGeometry::common_surface), else the mesh's
    // boundary. Surface loads act on the mesh's own boundary lifted to the cells' curved
    // faces: the domain fem solves on.
    const BoundarySurface boundary =
        constraints_.empty() ? boundary_surface(mesh_) : forest_boundary_surface(*forest_, mesh_);
    surface_.load_surface = boundary.surface;
    surface_.lift = lagrange_surface_lift(mesh_, boundary);
    surface_.surface = geometry.common_surface() ? *geometry.common_surface() : boundary.surface;
    surface_.common = geometry.common_surface() != nullptr;
    surface_.evaluator = std::make_unique<LagrangeBasisEvaluator>(mesh_, &constraints_);
  }

  const Discretization& discretization() const override { return *discretization_; }
  nlohmann::json element_counts() const override {
    return {{std::string(element_name(mesh_.element_type)), mesh_.cells.rows()}};
  }
  long long quadrature_points() const override { return discretization_->elements().whole_point_count(); }
  double quadrature_seconds() const override { return quadrature_seconds_; }
  UnstructuredGrid volume_grid(const Eigen::VectorXd& displacement) const override {
    UnstructuredGrid grid = grid_from_volume_mesh(mesh_);
    add_nodal_displacement(grid, constraints_.all_nodes(displacement));
    // Each cell's refinement level, to colour a refined grid by in ParaView.
    if (forest_)
      grid.cell_data.emplace_back(
          "level", Eigen::Map<const Eigen::VectorXi>(forest_->levels.data(), forest_->leaf_count()).cast<double>());
    return grid;
  }
  Eigen::VectorXd interpolate(const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& field) const override {
    return interpolate_at_nodes(free_nodes(), field);
  }
  nlohmann::json facts() const override {
    nlohmann::json facts = surface_.facts();
    if (forest_) facts["hanging_nodes"] = constraints_.hanging_nodes();
    return facts;
  }
  std::shared_ptr<const MethodMesh> mesh() const override {
    return std::make_shared<MeshOf<FemMesh>>(FemMesh{mesh_, std::nullopt, forest_, constraints_, nullptr});
  }
  std::string failure_hint() const override { return failure_hint_; }
  std::string cut_refusal() const override {
    if (scene_refines_) return "it does not cut a mesh that a refine event refines (hanging nodes) yet";
    return fem_cut_refusal(mesh_.element_type);
  }
  std::string refine_refusal(const RefineSpec& refine) const override {
    if (!forest_)
      return "it refines hexahedral grids only (discretization.fem: \"mesh\": \"grid\", hex8, hex20 or hex27); a "
             "tetrahedral mesh would need red-green closure or bisection to stay conforming, which fem does not have";
    return grid_refine_refusal(refine, scene_cuts_);
  }
  /// The grid's leaves whose stress the event marks split 1→8, the forest balanced 2:1
  /// (refine_hexahedral_grid).
  std::shared_ptr<const MethodMesh> refine_mesh(const SceneEvent& refine, const Eigen::VectorXd& displacement,
                                                const PrescribedTraction& boundary,
                                                nlohmann::json& facts) const override {
    std::optional<RefinedGrid> refined = refine_hexahedral_grid(
        *forest_, refine.refine, mean_cell_stresses(discretization_->elements(), materials_.pointers(), displacement),
        &boundary, facts);
    if (!refined) return nullptr;
    return std::make_shared<MeshOf<FemMesh>>(FemMesh{std::move(refined->mesh.mesh), std::nullopt,
                                                     std::move(refined->forest), std::move(refined->mesh.constraints),
                                                     nullptr});
  }
  /// The elements' own tetrahedra cut by the blade: the rebuild is a CutFemMethod.
  std::shared_ptr<const MethodMesh> cut_mesh(const SceneEvent& cut, nlohmann::json& facts) const override {
    return std::make_shared<MeshOf<FemMesh>>(
        FemMesh{mesh_, cut_embedded_tetrahedra(element_material(mesh_), cut.blade, facts), std::nullopt, {}, nullptr});
  }
  Eigen::MatrixXd transfer(const MethodInstance& previous, const Eigen::MatrixXd& fields) const override {
    const auto& before = dynamic_cast<const FemMethod&>(previous);
    return transfer_to_nodes(free_nodes(), before.free_nodes(), before.basis_evaluator(), fields);
  }
  /// The stiffness rule's tabulation, or every cell re-tabulated at the stronger rule.
  std::optional<FieldQuadrature> field_quadrature(int added_strength) const override {
    if (added_strength == 0)
      return nodal_field_quadrature(borrowed(discretization_->elements()), mesh_.nodes, quadrature_order_);
    const int strength = quadrature_order_ + added_strength;
    return nodal_field_quadrature(
        std::make_shared<TabulatedElements>(tabulate_lagrange(mesh_, strength, &constraints_)), mesh_.nodes, strength);
  }

private:
  // The nodes that carry the basis (#free nodes × 3): all but the hanging ones.
  Eigen::MatrixXd free_nodes() const { return mesh_.nodes.topRows(constraints_.free_nodes); }

  SceneMaterials materials_;
  VolumeMesh mesh_;
  std::optional<HexahedralForest> forest_;  ///< a hexahedral grid, refined or not
  NodeConstraints constraints_;             ///< its hanging nodes (free_nodes: every node when none hangs)
  bool scene_cuts_ = false, scene_refines_ = false;
  std::string failure_hint_;  // fem_cut_failure_hint in a scene that cuts
  std::unique_ptr<TabulatedDiscretization> discretization_;
  double quadrature_seconds_ = 0;
  int quadrature_order_ = 0;
};

// On handed elements: as they are, or cut (the virtual node algorithm).
std::unique_ptr<MethodInstance> rebuild_fem(const Scene& scene, const SceneGeometry& geometry,
                                            const MethodMesh& handed) {
  const FemMesh& mesh = method_mesh_as<FemMesh>(handed, "fem");
  if (mesh.material) return make_cut_fem_method(scene, geometry, mesh);
  return std::make_unique<FemMethod>(scene, geometry, &mesh);
}

}  // namespace

std::unique_ptr<MethodInstance> make_fem_method(const Scene& scene, const SceneGeometry& geometry) {
  return std::make_unique<FemMethod>(scene, geometry, nullptr);
}

const MethodDescription& fem_method() {
  static const MethodDescription method{fem_scene_block(), make_fem_method,
                                        "conforming Lagrange FEM (Tet4–Tet20, Hex8–Hex27)", rebuild_fem,
                                        fem_mesh_preview};
  return method;
}

}  // namespace altfem
