// Example 1: a cantilever under its own weight, step by step, checked against beam theory.
//
//   build/bin/ex1_cantilever [scenes/cantilever.json]
//
// What `altfem run --method fem` does, written out so each step can be read next to
// the mathematics. The scene (a 1 × 0.1 × 0.1 m beam of linear material, clamped at
// x = 0, under gravity) comes from the JSON file; nothing physical is set here.
#include <cmath>
#include <cstdio>

#include "shared/fem/fem_mesh.hpp"
#include "shared/fem/lagrange_discretization.hpp"
#include "shared/material/material.hpp"
#include "shared/scene/scene.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/solve/linear_solver.hpp"
#include "shared/solve/time_integrator.hpp"

using namespace altfem;

int main(int argc, char** argv) {
  const char* file = argc > 1 ? argv[1] : ALTFEM_SOURCE_DIR "/scenes/cantilever.json";

  // 1. The scene: validated, with every default resolved (docs/scene-schema.md).
  const Scene scene = load_scene(file);
  const SceneGeometry geometry = load_scene_geometry(scene);

  // 2. The mesh: a structured Hex20 grid of the beam's box (discretization.fem).
  const FemSpec fem_options = fem_spec(scene);
  VolumeMesh mesh = build_fem_mesh(fem_options, geometry);
  std::printf("mesh: %lld %s cells, %lld nodes\n", static_cast<long long>(mesh.cells.rows()),
              std::string(element_name(mesh.element_type)).c_str(), static_cast<long long>(mesh.nodes.rows()));

  // 3. The material: ψ(F) = μ ε:ε + λ/2 tr(ε)² with λ, μ from (E, ν).
  const auto material = make_material(*material_model_from_name(scene.material.model), scene.material.youngs_modulus,
                                      scene.material.poisson_ratio, scene.material.density);

  // 4. The discretization: every cell tabulated at its quadrature points (weights
  //    w_q |det J|, ∇N_a), the nodes of the clamped region constrained.
  const auto discretization =
      make_lagrange_discretization(mesh, *material, scene.dirichlet, fem_options.quadrature_order, file);
  const Discretization& fem = *discretization;

  // 5. Static equilibrium: minimise Ψ(u) − f·u with the load f_a = ∫ ρ g N_a dV (equal
  //    to M g, the consistent mass times gravity, for this partition-of-unity basis). Linear elasticity makes this one
  //    Newton step: K u = f.
  IntegratorOptions options;
  options.kind = IntegrationScheme::static_equilibrium;
  options.gravity = scene.gravity;
  options.tolerance = 1e-8;  // ‖K u − f‖ ≤ 1e-8 ‖M g‖
  const auto solver = make_linear_solver(LinearSolverOptions{});
  TimeIntegrator integrator(fem, *solver, options);
  State state;
  state.displacement = Eigen::VectorXd::Zero(fem.dof_count());
  state.velocity = state.displacement;
  state.time = 1.0;
  const StepReport report = integrator.step(state);
  std::printf("solved: %d DOFs, %d Newton iteration(s), residual %.2e\n", fem.dof_count(), report.newton_iterations,
              report.residual);

  // 6. The tip deflection: mean vertical displacement of the nodes on the free end.
  const auto& nodes = mesh.nodes;
  const double length = nodes.col(0).maxCoeff();
  double sum = 0;
  int count = 0;
  for (Eigen::Index node = 0; node < nodes.rows(); ++node)
    if (nodes(node, 0) > length - 1e-12) {
      sum += state.displacement[3 * node + 2];
      ++count;
    }
  const double deflection = -sum / count;

  // 7. Timoshenko beam theory for a uniform load q = ρ g A on a cantilever:
  //    δ = q L⁴ / (8 E I) + q L² / (2 κ G A), I = b h³ / 12, κ = 5/6 for a rectangle.
  const double width = nodes.col(1).maxCoeff() - nodes.col(1).minCoeff();
  const double height = nodes.col(2).maxCoeff() - nodes.col(2).minCoeff();
  const double area = width * height, inertia = width * std::pow(height, 3) / 12.0;
  const double E = scene.material.youngs_modulus, nu = scene.material.poisson_ratio;
  const double q = scene.material.density * scene.gravity.norm() * area;
  const double shear_modulus = E / (2 * (1 + nu));
  const double theory =
      q * std::pow(length, 4) / (8 * E * inertia) + q * length * length / (2 * 5.0 / 6.0 * shear_modulus * area);
  const double relative = std::abs(deflection - theory) / theory;
  std::printf("tip deflection %.6e m, Timoshenko %.6e m, difference %.2f%%\n", deflection, theory, 100 * relative);
  const bool verified = relative < 0.05;
  std::printf("%s: tip deflection within 5%% of beam theory\n", verified ? "verified" : "NOT verified");
  return verified ? 0 : 1;
}
