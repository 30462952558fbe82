#pragma once
// A test helper: the static equilibrium of a scene (with --set style overrides) by one
// method, as the displacement of the method's embedded surface vertices.
#include <filesystem>
#include <string>
#include <vector>

#include "shared/scene/scene_override.hpp"
#include "shared/simulation/method_instance.hpp"
#include "shared/solve/time_integrator.hpp"

namespace altfem::dg::test {

struct StaticSurface {
  int dofs;
  Eigen::MatrixXd vertices;      ///< #vertices × 3, at rest
  Eigen::MatrixXd displacement;  ///< #vertices × 3
  Eigen::MatrixXi triangles;     ///< #triangles × 3
};

inline StaticSurface static_surface(const std::filesystem::path& scene_file, const MethodFactory& factory,
                                    const std::vector<std::string>& assignments) {
  std::vector<SceneOverride> overrides;
  for (const auto& assignment : assignments) overrides.push_back(parse_scene_override(assignment));
  const Scene scene = load_scene(scene_file, overrides);
  const SceneGeometry geometry = load_scene_geometry(scene);
  const auto method = factory(scene, geometry);
  const Discretization& discretization = method->discretization();
  const auto solver = make_linear_solver({});
  IntegratorOptions options;
  options.kind = IntegrationScheme::static_equilibrium;
  options.gravity = scene.gravity;
  TimeIntegrator integrator(discretization, *solver, options);
  State state{Eigen::VectorXd::Zero(discretization.dof_count()), Eigen::VectorXd::Zero(discretization.dof_count())};
  integrator.apply_constraints(state);
  integrator.step(state);
  return {discretization.dof_count(), method->embedded_surface().vertices, method->embedded_displacement(state.displacement),
          method->embedded_surface().triangles};
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
