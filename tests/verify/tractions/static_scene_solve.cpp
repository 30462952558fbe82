#include "tests/verify/tractions/static_scene_solve.hpp"

#include <stdexcept>

#include "app/method_registry.hpp"
#include "shared/fem/lagrange_basis_evaluator.hpp"
#include "shared/fem/lagrange_discretization.hpp"
#include "shared/fem/lagrange_surface_lift.hpp"
#include "shared/mesh/boundary_surface.hpp"
#include "shared/simulation/surface_traction.hpp"
#include "shared/solve/time_integrator.hpp"

namespace altfem::test {

Eigen::VectorXd solve_static(const Discretization& discretization, std::vector<TimeDependentLoad> loads,
                             double tolerance) {
  const TimedDiscretization loaded(discretization, std::move(loads));
  const auto linear_solver = make_linear_solver({});
  IntegratorOptions options;
  options.tolerance = tolerance;
  TimeIntegrator integrator(loaded, *linear_solver, options);
  // Statics evaluate loads and motions at t = 1 s, as run_simulation does.
  State state{Eigen::VectorXd::Zero(loaded.dof_count()), Eigen::VectorXd::Zero(loaded.dof_count()), 1.0, 0};
  integrator.step(state);
  return state.displacement;
}

RegionSelector half_space(const Eigen::Vector3d& point, const Eigen::Vector3d& normal) {
  RegionSelector region;
  region.kind = RegionKind::half_space;
  region.point = point;
  region.normal = normal;
  return region;
}

Eigen::VectorXd solve_lagrange_static(const VolumeMesh& mesh, const Material& material,
                                      const std::vector<DirichletCondition>& conditions, SurfaceTraction load) {
  const auto discretization = make_lagrange_discretization(mesh, material, conditions, 6);
  load.pointer = "/loads/traction/0";
  const BoundarySurface boundary = boundary_surface(mesh);
  const LagrangeBasisEvaluator evaluator(mesh);
  const Eigen::AlignedBox3d bounds(mesh.nodes.colwise().minCoeff().transpose(), mesh.nodes.colwise().maxCoeff().transpose());
  const double tolerance = region_tolerance(bounds);
  const SurfaceTractionLoad traction({load}, boundary.surface, evaluator, discretization->dof_count(), tolerance, "test",
                                     lagrange_surface_lift(mesh, boundary));
  return solve_static(*discretization, {traction}, 1e-12);
}

StaticSolution solve_static_scene(Scene scene, const std::string& method_name, double tolerance) {
  StaticSolution solution;
  solution.scene = std::move(scene);
  solution.geometry = load_scene_geometry(solution.scene);
  const MethodDescription* description = nullptr;
  for (const auto& method : cli::registered_methods())
    if (method.scene_block.name == method_name) description = &method;
  if (!description) throw std::invalid_argument("no method " + method_name);
  solution.method = description->factory(solution.scene, solution.geometry);
  std::vector<TimeDependentLoad> loads;
  if (auto tractions = surface_traction_load(solution.scene, solution.geometry.bounds, *solution.method))
    loads.push_back(std::move(tractions));
  solution.displacement = solve_static(solution.method->discretization(), std::move(loads), tolerance);
  return solution;
}

StaticSolution solve_static_scene(const std::string& scene_text, const std::string& method_name, double tolerance) {
  return solve_static_scene(parse_scene(scene_text, "traction_scene.json"), method_name, tolerance);
}

}  // namespace altfem::test
