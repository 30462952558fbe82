#include "tests/support/static_solve.hpp"

#include <cmath>
#include <stdexcept>

#include "app/method_registry.hpp"
#include "shared/fem/lagrange_basis_evaluator.hpp"
#include "shared/fem/lagrange_discretization.hpp"
#include "shared/fem/lagrange_surface_lift.hpp"
#include "shared/mesh/boundary_surface.hpp"
#include "shared/scene/scene_override.hpp"
#include "shared/simulation/simulation.hpp"
#include "shared/simulation/surface_traction.hpp"
#include "shared/solve/time_integrator.hpp"

namespace altfem::test {

namespace {

// Newton to `tolerance` for static equilibrium at t = 1 s, with the scene's gravity and
// linear solver when a scene and its method are given (else none and CHOLMOD).
Eigen::VectorXd solve(const Discretization& discretization, std::vector<TimeDependentLoad> loads, double tolerance,
                      const Scene* scene, const MethodInstance* method) {
  double assembly_seconds = 0;
  const TimedDiscretization loaded(discretization, std::move(loads), assembly_seconds);
  const auto linear_solver = make_linear_solver(scene ? linear_solver_options(*scene, *method) : LinearSolverOptions{});
  IntegratorOptions options;
  options.kind = IntegrationScheme::static_equilibrium;
  options.tolerance = tolerance;
  if (scene) options.gravity = scene->gravity;
  TimeIntegrator integrator(loaded, *linear_solver, options);
  // Statics evaluate loads and motions at t = 1 s, as run_simulation does.
  State state{Eigen::VectorXd::Zero(loaded.dof_count()), Eigen::VectorXd::Zero(loaded.dof_count()), 1.0, 0};
  integrator.apply_constraints(state);
  integrator.step(state);
  return state.displacement;
}

}  // namespace

const MethodDescription& registered_method(const std::string& name) {
  for (const auto& method : cli::registered_methods())
    if (method.scene_block.name == name) return method;
  throw std::invalid_argument("no method " + name);
}

StaticRun static_run(Scene scene, const MethodFactory& factory, double tolerance) {
  StaticRun run;
  run.scene = std::make_unique<Scene>(std::move(scene));
  run.geometry = std::make_unique<SceneGeometry>(load_scene_geometry(*run.scene));
  run.method = factory(*run.scene, *run.geometry);
  std::vector<TimeDependentLoad> loads;
  if (auto tractions = surface_traction_load(*run.scene, run.geometry->bounds, *run.method))
    loads.push_back(std::move(tractions));
  run.displacement = solve(run.method->discretization(), std::move(loads), tolerance, run.scene.get(), run.method.get());
  return run;
}

StaticRun static_run(const std::filesystem::path& scene_file, const MethodFactory& factory,
                     const std::vector<std::string>& assignments, double tolerance) {
  std::vector<SceneOverride> overrides;
  for (const auto& assignment : assignments) overrides.push_back(parse_scene_override(assignment));
  return static_run(load_scene(scene_file, overrides), factory, tolerance);
}

StaticRun static_run_text(const std::string& scene_text, const std::string& method_name, double tolerance) {
  return static_run(parse_scene(scene_text, "traction_scene.json"), registered_method(method_name).factory, tolerance);
}

Eigen::VectorXd solve_static(const Discretization& discretization, std::vector<TimeDependentLoad> loads,
                             double tolerance) {
  return solve(discretization, std::move(loads), tolerance, nullptr, nullptr);
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
  const Eigen::AlignedBox3d bounds(mesh.nodes.colwise().minCoeff().transpose(),
                                   mesh.nodes.colwise().maxCoeff().transpose());
  const double tolerance = region_tolerance(bounds);
  const SurfaceTractionLoad traction({load}, boundary.surface, evaluator, discretization->dof_count(), tolerance,
                                     "test", lagrange_surface_lift(mesh, boundary));
  return solve_static(*discretization, {traction}, 1e-12);
}

StaticSurface static_surface(const std::filesystem::path& scene_file, const MethodFactory& factory,
                             const std::vector<std::string>& assignments) {
  const StaticRun run = static_run(scene_file, factory, assignments);
  return {run.method->discretization().dof_count(), run.method->embedded_surface().vertices,
          run.method->embedded_displacement(run.displacement), run.method->embedded_surface().triangles};
}

double mean_on_plane(const StaticSurface& surface, int axis, double value, int component, double tolerance) {
  double sum = 0;
  int count = 0;
  for (Eigen::Index v = 0; v < surface.vertices.rows(); ++v)
    if (std::abs(surface.vertices(v, axis) - value) < tolerance) {
      sum += surface.displacement(v, component);
      ++count;
    }
  return count > 0 ? sum / count : std::nan("");
}

}  // namespace altfem::test
