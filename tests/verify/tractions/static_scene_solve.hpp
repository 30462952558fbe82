#pragma once
// Static equilibrium as `altfem run` solves it (the method's discretization plus the
// scene's surface loads), without writing output.
#include <Eigen/Core>
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

/// The displacement (#dofs) of static equilibrium at t = 1 s under the discretization's
/// own external force plus `loads`: Newton to `tolerance` (solver.tolerance's rule).
Eigen::VectorXd solve_static(const Discretization& discretization, std::vector<TimeDependentLoad> loads,
                             double tolerance = 1e-10);

/// The region (x − point)·normal ≤ 0.
RegionSelector half_space(const Eigen::Vector3d& point, const Eigen::Vector3d& normal);

/// Static equilibrium of the fem discretization of a Lagrange mesh (quadrature strength
/// 6) under one surface load on its boundary's curved faces, integrated as `altfem run`
/// integrates it for fem.
Eigen::VectorXd solve_lagrange_static(const VolumeMesh& mesh, const Material& material,
                                      const std::vector<DirichletCondition>& conditions, SurfaceTraction load);

struct StaticSolution {
  Scene scene;
  SceneGeometry geometry;
  std::unique_ptr<MethodInstance> method;
  Eigen::VectorXd displacement;  ///< #dofs
};

/// Builds the registered method `method_name` for a static scene and solves it with
/// the scene's surface loads.
StaticSolution solve_static_scene(Scene scene, const std::string& method_name, double tolerance = 1e-10);
/// The same for scene text (relative paths resolve against the working folder).
StaticSolution solve_static_scene(const std::string& scene_text, const std::string& method_name,
                                  double tolerance = 1e-10);

}  // namespace altfem::test
