// A scene a distributed test builds on every rank (and again on one process, under
// ranks::Alone), and its PETSc solve: shared by the checks of the shares and of the
// iterations (issue #37, step 2).
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "shared/scene/scene_geometry.hpp"
#include "shared/scene/scene_override.hpp"
#include "shared/simulation/simulation.hpp"
#include "tests/support/static_solve.hpp"

namespace altfem::test {

struct TwoRankCase {
  std::string name, method, scene;
  std::vector<std::string> assignments;
};

// gtest names a failing case by its name, not its bytes.
inline void PrintTo(const TwoRankCase& c, std::ostream* out) { *out << c.name; }

// A scene, its geometry and the simulation built from them (which refers to both).
struct Built {
  explicit Built(const TwoRankCase& c, const std::vector<std::string>& more = {}) {
    std::vector<SceneOverride> overrides;
    for (const std::string& assignment : c.assignments) overrides.push_back(parse_scene_override(assignment));
    for (const std::string& assignment : more) overrides.push_back(parse_scene_override(assignment));
    scene = std::make_unique<Scene>(load_scene(std::filesystem::path(ALTFEM_SOURCE_DIR) / c.scene, overrides));
    geometry = std::make_unique<SceneGeometry>(load_scene_geometry(*scene));
    simulation = std::make_unique<Simulation>(*scene, *geometry, c.method, registered_method(c.method).factory);
  }
  std::unique_ptr<Scene> scene;
  std::unique_ptr<SceneGeometry> geometry;
  std::unique_ptr<Simulation> simulation;
};

struct Solved {
  Eigen::VectorXd displacement;
  int newton_iterations = 0;
  long long linear_iterations = 0;
};

// The scene's first step solved by PETSc (CG + GAMG, the defaults) to a relative residual of
// `tolerance`. The method's smoother on GAMG's finest level (solver.method_smoother: fcm's
// Schwarz blocks, dg's block Jacobi) is set up from the ranks' shares and applied to the
// gathered residual; on higher-order fem and fcm and on dg GAMG works on the coarser space
// inside (solver.p_multigrid), across the partition.
inline Solved solve_first_step(const TwoRankCase& c, const std::string& tolerance) {
  Built built(c, {"solver/linear=petsc", "solver/linear_tolerance=" + tolerance});
  const StepReport report = built.simulation->integrator().step(built.simulation->state());
  return {built.simulation->state().displacement, report.newton_iterations, report.linear_iterations};
}

}  // namespace altfem::test
