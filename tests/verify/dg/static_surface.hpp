#pragma once
// A test helper: the static equilibrium of a scene (with --set style overrides) by one
// method and the scene's linear solver, as its coefficients (static_run) or as the displacement of the method's
// embedded surface vertices (static_surface).
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "shared/scene/scene_override.hpp"
#include "shared/simulation/run_simulation.hpp"
#include "shared/simulation/method_instance.hpp"
#include "shared/solve/time_integrator.hpp"

namespace altfem::dg::test {

struct StaticSurface {
  int dofs;
  Eigen::MatrixXd vertices;      ///< #vertices × 3, at rest
  Eigen::MatrixXd displacement;  ///< #vertices × 3
  Eigen::MatrixXi triangles;     ///< #triangles × 3
};

/// A static solve kept with what it was computed from (the method may refer to its scene
/// and geometry, so each lives at a fixed address).
struct StaticRun {
  std::unique_ptr<Scene> scene;
  std::unique_ptr<SceneGeometry> geometry;
  std::unique_ptr<MethodInstance> method;
  Eigen::VectorXd displacement;  ///< #dofs, at t = 1 s as `altfem run` solves statics
};

inline StaticRun static_run(const std::filesystem::path& scene_file, const MethodFactory& factory,
                            const std::vector<std::string>& assignments) {
  std::vector<SceneOverride> overrides;
  for (const auto& assignment : assignments) overrides.push_back(parse_scene_override(assignment));
  StaticRun run;
  run.scene = std::make_unique<Scene>(load_scene(scene_file, overrides));
  run.geometry = std::make_unique<SceneGeometry>(load_scene_geometry(*run.scene));
  run.method = factory(*run.scene, *run.geometry);
  const Discretization& discretization = run.method->discretization();
  const auto solver = make_linear_solver(linear_solver_options(*run.scene, discretization));
  IntegratorOptions options;
  options.kind = IntegrationScheme::static_equilibrium;
  options.gravity = run.scene->gravity;
  TimeIntegrator integrator(discretization, *solver, options);
  State state{Eigen::VectorXd::Zero(discretization.dof_count()), Eigen::VectorXd::Zero(discretization.dof_count())};
  state.time = 1;
  integrator.apply_constraints(state);
  integrator.step(state);
  run.displacement = std::move(state.displacement);
  return run;
}

inline StaticSurface static_surface(const std::filesystem::path& scene_file, const MethodFactory& factory,
                                    const std::vector<std::string>& assignments) {
  const StaticRun run = static_run(scene_file, factory, assignments);
  return {run.method->discretization().dof_count(), run.method->embedded_surface().vertices,
          run.method->embedded_displacement(run.displacement), run.method->embedded_surface().triangles};
}

/// The mean of displacement component `component` over the vertices whose coordinate
/// `axis` is within `tolerance` of `value` (NaN if none is).
inline double mean_on_plane(const StaticSurface& surface, int axis, double value, int component, double tolerance) {
  double sum = 0;
  int count = 0;
  for (Eigen::Index v = 0; v < surface.vertices.rows(); ++v)
    if (std::abs(surface.vertices(v, axis) - value) < tolerance) {
      sum += surface.displacement(v, component);
      ++count;
    }
  return count > 0 ? sum / count : std::nan("");
}

}  // namespace altfem::dg::test
