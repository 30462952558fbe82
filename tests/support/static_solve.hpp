#pragma once
// Test helpers: static equilibrium as `altfem run` solves it (the method's discretization,
// the scene's surface loads and gravity, the scene's linear solver), without writing
// output — by a registered method or any factory, from a scene, its file (with --set
// style overrides) or its text — and what tests read off the solution.
#include <Eigen/Core>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "shared/material/material.hpp"
#include "shared/mesh/volume_mesh.hpp"
#include "shared/scene/scene.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/simulation/method_instance.hpp"
#include "shared/simulation/timed_discretization.hpp"

namespace altfem::test {

/// A static solve kept with what it was computed from (the method may refer to its scene
/// and geometry, so each lives at a fixed address).
struct StaticRun {
  std::unique_ptr<Scene> scene;
  std::unique_ptr<SceneGeometry> geometry;
  std::unique_ptr<MethodInstance> method;
  Eigen::VectorXd displacement;  ///< #dofs, at t = 1 s as `altfem run` solves statics
};

/// The registered method called `name` (std::invalid_argument when there is none).
const MethodDescription& registered_method(const std::string& name);

/// Static equilibrium of `scene` by `factory`'s method: Newton to `tolerance` (the rule
/// of solver.tolerance).
StaticRun static_run(Scene scene, const MethodFactory& factory, double tolerance = 1e-5);
/// The same for a scene file with `--set` style assignments.
StaticRun static_run(const std::filesystem::path& scene_file, const MethodFactory& factory,
                     const std::vector<std::string>& assignments, double tolerance = 1e-5);
/// The same for scene text (relative paths resolve against the working folder) and a
/// registered method.
StaticRun static_run_text(const std::string& scene_text, const std::string& method_name, double tolerance = 1e-10);

/// The displacement (#dofs) of static equilibrium at t = 1 s under the discretization's
/// own external force plus `loads`.
Eigen::VectorXd solve_static(const Discretization& discretization, std::vector<TimeDependentLoad> loads,
                             double tolerance = 1e-10);

/// The region (x − point)·normal ≤ 0.
RegionSelector half_space(const Eigen::Vector3d& point, const Eigen::Vector3d& normal);

/// Static equilibrium of the fem discretization of a Lagrange mesh (quadrature strength
/// 6) under one surface load on its boundary's curved faces, integrated as `altfem run`
/// integrates it for fem.
Eigen::VectorXd solve_lagrange_static(const VolumeMesh& mesh, const Material& material,
                                      const std::vector<DirichletCondition>& conditions, SurfaceTraction load);

/// A solution on the method's embedded surface.
struct StaticSurface {
  int dofs;
  Eigen::MatrixXd vertices;      ///< #vertices × 3, at rest
  Eigen::MatrixXd displacement;  ///< #vertices × 3
  Eigen::MatrixXi triangles;     ///< #triangles × 3
};

/// static_run's solution on the embedded surface.
StaticSurface static_surface(const std::filesystem::path& scene_file, const MethodFactory& factory,
                             const std::vector<std::string>& assignments);

/// The mean of displacement component `component` over the vertices whose coordinate
/// `axis` is within `tolerance` of `value` (NaN if none is).
double mean_on_plane(const StaticSurface& surface, int axis, double value, int component, double tolerance);

}  // namespace altfem::test
