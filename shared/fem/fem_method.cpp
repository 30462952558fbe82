#include "shared/fem/fem_method.hpp"

#include <chrono>

#include "shared/fem/fem_mesh.hpp"
#include "shared/fem/lagrange_basis_evaluator.hpp"
#include "shared/fem/lagrange_discretization.hpp"
#include "shared/fem/lagrange_surface_lift.hpp"
#include "shared/fem/tabulate_lagrange.hpp"
#include "shared/mesh/boundary_surface.hpp"
#include "shared/simulation/basis_embedding.hpp"
#include "shared/simulation/nodal_basis.hpp"
#include "shared/simulation/scene_materials.hpp"

namespace altfem {

namespace {

class FemMethod final : public MethodInstance {
public:
  FemMethod(const Scene& scene, const SceneGeometry& geometry)
      : materials_(scene) {
    const FemSpec fem = fem_spec(scene);
    quadrature_order_ = fem.quadrature_order;
    mesh_ = build_fem_mesh(fem, geometry);
    const auto start = std::chrono::steady_clock::now();
    discretization_ = make_lagrange_discretization(mesh_, materials_.pointers(), materials_.ids_of(corner_centroids(mesh_)),
                                                   scene.dirichlet, fem.quadrature_order,
                                                   scene.file.string());
    quadrature_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // The surface every method deforms (SceneGeometry::common_surface), else the mesh's
    // boundary. Surface loads act on the mesh's own boundary lifted to the cells' curved
    // faces: the domain fem solves on.
    const BoundarySurface boundary = boundary_surface(mesh_);
    load_surface_ = boundary.surface;
    lift_ = lagrange_surface_lift(mesh_, boundary);
    surface_ = geometry.common_surface() ? *geometry.common_surface() : boundary.surface;
    evaluator_ = std::make_unique<LagrangeBasisEvaluator>(mesh_);
    embedding_ = std::make_unique<BasisEmbedding>(*evaluator_, surface_.vertices);
  }

  const Discretization& discretization() const override { return *discretization_; }
  nlohmann::json element_counts() const override {
    return {{std::string(element_name(mesh_.element_type)), mesh_.cells.rows()}};
  }
  long long quadrature_points() const override { return discretization_->elements().point_count(); }
  double quadrature_seconds() const override { return quadrature_seconds_; }
  UnstructuredGrid volume_grid(const Eigen::VectorXd& displacement) const override {
    UnstructuredGrid grid = grid_from_volume_mesh(mesh_);
    add_nodal_displacement(grid, displacement);
    return grid;
  }
  const SurfaceMesh& embedded_surface() const override { return surface_; }
  const SurfaceMesh& load_surface() const override { return load_surface_; }
  const ElementBasisEvaluator& basis_evaluator() const override { return *evaluator_; }
  SurfaceLift surface_lift() const override { return lift_; }
  Eigen::MatrixXd embedded_displacement(const Eigen::VectorXd& displacement) const override {
    return embedding_->displacement(displacement);
  }
  Eigen::VectorXd interpolate(const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& field) const override {
    return interpolate_at_nodes(mesh_.nodes, field);
  }
  nlohmann::json facts() const override {
    return embedding_facts(surface_, *embedding_);
  }
  /// The stiffness rule's tabulation, or every cell re-tabulated at the stronger rule.
  std::optional<FieldQuadrature> field_quadrature(int added_strength) const override {
    if (added_strength == 0)
      return nodal_field_quadrature(borrowed(discretization_->elements()), mesh_.nodes, quadrature_order_);
    const int strength = quadrature_order_ + added_strength;
    return nodal_field_quadrature(std::make_shared<TabulatedElements>(tabulate_lagrange(mesh_, strength)), mesh_.nodes,
                                  strength);
  }

private:
  SceneMaterials materials_;
  VolumeMesh mesh_;
  std::unique_ptr<TabulatedDiscretization> discretization_;
  SurfaceMesh surface_;
  SurfaceMesh load_surface_;
  SurfaceLift lift_;  // empty with the scene's own surface
  std::unique_ptr<LagrangeBasisEvaluator> evaluator_;
  std::unique_ptr<BasisEmbedding> embedding_;
  double quadrature_seconds_ = 0;
  int quadrature_order_ = 0;
};

}  // namespace

std::unique_ptr<MethodInstance> make_fem_method(const Scene& scene, const SceneGeometry& geometry) {
  return std::make_unique<FemMethod>(scene, geometry);
}

const MethodDescription& fem_method() {
  static const MethodDescription method{fem_scene_block(), make_fem_method,
                                        "conforming Lagrange FEM (Tet4–Tet20, Hex8–Hex27)"};
  return method;
}

}  // namespace altfem
