// Example 2: how a new discretization plugs into altfem's core, in one file.
//
//   build/bin/ex2_new_method [scenes/cantilever.json]
//
// The "method" here is small but not conforming: the cantilever's Hex8 cells each get
// their OWN copy of their 8 nodes, so neighbouring cells share no basis function, and
// they are glued by a penalty on the displacement jump across each shared face,
//   E_f(u) = η_f / 2 ∫_f |u⁻ − u⁺|² dA,  η_f = η E area (1/vol⁻ + 1/vol⁺)
// (the Babuška–Zlámal flux of Kaufmann et al. 2009, eqs. (19)-(20)). A method supplies
// exactly three things (docs/architecture.md, "Adding a method"): tabulated volume
// elements, its extra terms as face kernels, and its boundary conditions; the core
// assembles, solves and integrates in time. As η grows the glued beam must deflect like
// the conforming one (the penalty's consistency error is O(1/η)): that is what this
// program prints and checks.
#include <cmath>
#include <cstdio>

#include "shared/assembly/face_assembler.hpp"
#include "shared/assembly/jump_penalty_kernel.hpp"
#include "shared/element/reference_element.hpp"
#include "shared/fem/lagrange_discretization.hpp"
#include "shared/fem/nodal_dirichlet.hpp"
#include "shared/fem/tabulate_lagrange.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "shared/quadrature/reference_rules.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/solve/time_integrator.hpp"

using namespace altfem;

// Mean u_z over the nodes on the free end x = max.
double tip_deflection(const VolumeMesh& mesh, const Eigen::VectorXd& u) {
  const double end = mesh.nodes.col(0).maxCoeff();
  double sum = 0;
  int count = 0;
  for (Eigen::Index node = 0; node < mesh.nodes.rows(); ++node)
    if (mesh.nodes(node, 0) > end - 1e-12) sum += u[3 * node + 2], ++count;
  return sum / count;
}

// Static equilibrium under gravity with any Discretization: one Newton step (linear material).
Eigen::VectorXd solve(const Discretization& discretization, const Scene& scene) {
  IntegratorOptions options;
  options.gravity = scene.gravity;
  options.tolerance = 1e-8;  // ‖K u − f‖ ≤ 1e-8 ‖f_gravity‖: round-off of one solve
  const auto solver = make_linear_solver({});
  TimeIntegrator integrator(discretization, *solver, options);
  State state{Eigen::VectorXd::Zero(discretization.dof_count()), Eigen::VectorXd::Zero(discretization.dof_count())};
  integrator.step(state);
  return state.displacement;
}

int main(int argc, char** argv) {
  const char* file = argc > 1 ? argv[1] : ALTFEM_SOURCE_DIR "/scenes/cantilever.json";
  const Scene scene = load_scene(file);
  const SceneGeometry geometry = load_scene_geometry(scene);
  const auto material = make_material(*material_model_from_name(scene.material.model), scene.material.youngs_modulus,
                                      scene.material.poisson_ratio, scene.material.density);
  const VolumeMesh conforming = structured_grid(geometry.bounds, {8, 1, 1}, ElementType::hex8);

  // 1. The mesh of the method: every cell with its own copy of its nodes.
  VolumeMesh glued{ElementType::hex8, Eigen::MatrixXd(8 * conforming.cells.rows(), 3), conforming.cells};
  for (Eigen::Index cell = 0; cell < conforming.cells.rows(); ++cell)
    for (int a = 0; a < 8; ++a) {
      glued.cells(cell, a) = static_cast<int>(8 * cell + a);
      glued.nodes.row(8 * cell + a) = conforming.nodes.row(conforming.cells(cell, a));
    }

  // 2. The faces between cell c (minus side, its face ξ = +1) and c + 1 (plus side,
  //    ξ = −1): per point the traces of both cells' 8 functions, 16 in all.
  const ReferenceElement& hex8 = reference_element(ElementType::hex8);
  const Eigen::Vector3d cell_size = geometry.bounds.sizes().cwiseQuotient(Eigen::Vector3d(8, 1, 1));
  const QuadratureRule face_rule = quad_rule(3);
  TabulatedFaces faces;
  for (int cell = 0; cell + 1 < glued.cells.rows(); ++cell) {
    const Eigen::Index points = face_rule.weights.size();
    std::vector<int> basis;
    for (int side = 0; side < 2; ++side)
      for (int a = 0; a < 8; ++a) basis.push_back(glued.cells(cell + side, a));
    Eigen::MatrixXd values_minus = Eigen::MatrixXd::Zero(points, 16), values_plus = values_minus;
    Eigen::MatrixXd gradients_minus = Eigen::MatrixXd::Zero(16 * points, 3), gradients_plus = gradients_minus;
    Eigen::VectorXd shape(8);
    Eigen::MatrixXd shape_gradients(8, 3);
    for (Eigen::Index q = 0; q < points; ++q)
      for (int side = 0; side < 2; ++side) {
        const Eigen::Vector3d xi(side == 0 ? 1.0 : -1.0, face_rule.points(q, 0), face_rule.points(q, 1));
        hex8.evaluate(xi, shape);
        hex8.evaluate_gradients(xi, shape_gradients);
        // An axis-aligned box cell: ∇N = (∂N/∂ξ) diag(2 / cell size).
        const Eigen::MatrixXd physical = shape_gradients * (2.0 * cell_size.cwiseInverse()).asDiagonal();
        (side == 0 ? values_minus : values_plus).block(q, 8 * side, 1, 8) = shape.transpose();
        (side == 0 ? gradients_minus : gradients_plus).middleRows(16 * q + 8 * side, 8) = physical;
      }
    const Eigen::VectorXd weights = face_rule.weights * (cell_size.y() * cell_size.z() / 4);
    faces.add(basis, std::span<const double>(weights.data(), weights.size()),
              Eigen::RowVector3d::UnitX().replicate(points, 1), values_minus, values_plus, gradients_minus,
              gradients_plus, cell, cell + 1);
  }

  // 3. For each penalty: the parts, assembled into a Discretization, solved.
  const double conforming_tip = tip_deflection(
      conforming, solve(*make_lagrange_discretization(conforming, *material, scene.dirichlet, 2, file), scene));
  std::printf("conforming Hex8 beam: tip deflection %.6e m\n\n%8s %16s %12s\n", conforming_tip, "eta", "glued tip [m]",
              "rel. diff.");
  const double volume = cell_size.prod(), area = cell_size.y() * cell_size.z();
  double previous_difference = INFINITY;
  bool converging = true;
  for (const double eta : {1e0, 1e1, 1e2, 1e3, 1e4}) {
    DiscretizationParts parts;
    parts.elements = tabulate_lagrange(glued, 2);
    parts.materials = {material.get()};
    const std::vector<double> penalties(faces.size(), eta * scene.material.youngs_modulus * area * 2 / volume);
    parts.terms.push_back(std::make_unique<FaceAssembler<JumpPenaltyKernel>>(faces, JumpPenaltyKernel(penalties)));
    parts.dirichlet = nodal_dirichlet(glued.nodes, scene.dirichlet, file, "the glued mesh");
    const TabulatedDiscretization discretization(std::move(parts));
    const double tip = tip_deflection(glued, solve(discretization, scene));
    const double difference = std::abs(tip - conforming_tip) / std::abs(conforming_tip);
    std::printf("%8.0e %16.6e %12.2e\n", eta, tip, difference);
    converging = converging && difference < previous_difference;
    previous_difference = difference;
  }
  const bool ok = converging && previous_difference < 1e-3;
  std::printf("\nthe glued beam converges to the conforming one as eta grows: %s\n", ok ? "yes" : "NO");
  return ok ? 0 : 1;
}
