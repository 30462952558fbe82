// A release event (docs/scene-schema.md, "Events") with every method, on a cantilever
// held at its clamped end and at its tip; the tip's condition is released at 0.1 s.
//   - Afterwards the beam oscillates about the free cantilever's static deflection: it
//     overshoots it (a load applied suddenly to an oscillator at rest swings to twice its
//     static response, less the damping), and the Rayleigh damping (α = 20/s, ζ ≈ 0.3 for
//     the first bending mode) brings it to rest there, checked against the same method's
//     static solution of the free cantilever and against fem's.
//   - The released run equals a fresh run of the free cantilever started from the state
//     the release acted on (transferred into the fresh method's basis).
//   - Released between static load steps, the linear cantilever ends at the free one's
//     equilibrium.
//   - transfer() onto a finer mesh reproduces the polynomials of the basis.
//   - PETSc's CG + GAMG follows the release as CHOLMOD does.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <memory>

#include "app/method_registry.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/scene/scene_override.hpp"
#include "shared/simulation/simulation.hpp"
#include "shared/solve/petsc_solver.hpp"

namespace altfem {
namespace {

const std::filesystem::path scene_file =
    std::filesystem::path(ALTFEM_SOURCE_DIR) / "tests/verify/events/scenes/held_cantilever.json";

// The mean vertical displacement of the embedded surface's vertices at the tip (x = 1).
double tip_deflection(const Simulation& simulation) {
  const MethodInstance& method = simulation.method();
  const Eigen::MatrixXd moved = method.embedded_displacement(simulation.state().displacement);
  const Eigen::MatrixXd& vertices = method.embedded_surface().vertices;
  double sum = 0;
  int count = 0;
  for (Eigen::Index v = 0; v < vertices.rows(); ++v)
    if (vertices(v, 0) > 1 - 1e-9) {
      sum += moved(v, 2);
      ++count;
    }
  return sum / count;
}

// The free cantilever (the clamp alone) at static equilibrium under gravity.
double static_free_deflection(const std::string& method_name) {
  Scene scene =
      load_scene(scene_file, {parse_scene_override("time={\"static\": true}"), parse_scene_override("events=[]")});
  scene.dirichlet.pop_back();  // the tip
  const SceneGeometry geometry = load_scene_geometry(scene);
  Simulation simulation(scene, geometry, method_name, cli::find_method(method_name).factory);
  simulation.integrator().step(simulation.state());
  return tip_deflection(simulation);
}

class Release : public ::testing::TestWithParam<std::string> {};

TEST_P(Release, TheBeamOscillatesAboutTheFreeStaticDeflection) {
  const Scene scene = load_scene(scene_file);
  const SceneGeometry geometry = load_scene_geometry(scene);
  Simulation simulation(scene, geometry, GetParam(), cli::find_method(GetParam()).factory);
  const double free = static_free_deflection(GetParam());
  const double fem = GetParam() == "fem" ? free : static_free_deflection("fem");
  ASSERT_LT(free, 0);
  double lowest = 0, held = 0;
  bool released = false;
  for (int step = 1; step <= scene.time.steps; ++step) {
    simulation.integrator().step(simulation.state());
    if (!released && simulation.state().time >= scene.events.front().time - 1e-12) {
      held = tip_deflection(simulation);
      simulation.apply(scene.events.front());
      released = true;
    }
    lowest = std::min(lowest, tip_deflection(simulation));
  }
  ASSERT_TRUE(released);
  std::printf(
      "%-8s tip deflection: free static %.5f m (fem %.5f), lowest after the release %.5f (%.2f x), "
      "at the end %.5f\n",
      GetParam().c_str(), free, fem, lowest, lowest / free, tip_deflection(simulation));
  EXPECT_NEAR(held, 0.0, 1e-12) << "the held tip does not move";
  EXPECT_LT(lowest, 1.15 * free) << "no overshoot past the static deflection " << free;
  EXPECT_NEAR(tip_deflection(simulation), free, 0.02 * std::abs(free));
  EXPECT_NEAR(free, fem, 0.1 * std::abs(fem)) << "the methods' free cantilevers disagree";
}

TEST_P(Release, EqualsAFreshRunFromTheReleasedState) {
  const Scene scene = load_scene(scene_file);
  const SceneGeometry geometry = load_scene_geometry(scene);
  Simulation released(scene, geometry, GetParam(), cli::find_method(GetParam()).factory);
  const int steps_before = 25;  // 0.1 s
  for (int step = 0; step < steps_before; ++step) released.integrator().step(released.state());
  released.apply(scene.events.front());

  Scene free_scene = scene;
  free_scene.dirichlet.pop_back();
  free_scene.events.clear();
  Simulation fresh(free_scene, geometry, GetParam(), cli::find_method(GetParam()).factory);
  Eigen::MatrixXd fields(released.state().displacement.size(), 2);
  fields << released.state().displacement, released.state().velocity;
  const Eigen::MatrixXd moved = fresh.method().transfer(released.method(), fields);
  State transferred = released.state();
  transferred.displacement = moved.col(0);
  transferred.velocity = moved.col(1);
  fresh.state() = transferred;
  for (int step = 0; step < 25; ++step) {
    released.integrator().step(released.state());
    fresh.integrator().step(fresh.state());
  }
  const Eigen::MatrixXd a = released.method().embedded_displacement(released.state().displacement);
  const Eigen::MatrixXd b = fresh.method().embedded_displacement(fresh.state().displacement);
  EXPECT_EQ(released.state().step, fresh.state().step);
  EXPECT_LT((a - b).cwiseAbs().maxCoeff(), 1e-9 * a.cwiseAbs().maxCoeff());
}

// Static load steps (time.load_steps = 4) with the release after load step 2: the
// material is linear, so the equilibrium does not depend on the path and the last step
// is the free cantilever's static solution.
TEST_P(Release, BetweenStaticLoadStepsGivesTheFreeCantilever) {
  const Scene scene = load_scene(scene_file, {parse_scene_override(R"(time={"static": true, "load_steps": 4})"),
                                              parse_scene_override("events/0/time=2")});
  const SceneGeometry geometry = load_scene_geometry(scene);
  Simulation simulation(scene, geometry, GetParam(), cli::find_method(GetParam()).factory);
  for (int step = 1; step <= 4; ++step) {
    simulation.state().load_factor = step / 4.0;
    simulation.integrator().step(simulation.state());
    EXPECT_EQ(simulation.state().step, step);
    if (step == 2) simulation.apply(scene.events.front());
  }
  const double free = static_free_deflection(GetParam());
  EXPECT_NEAR(tip_deflection(simulation), free, 1e-8 * std::abs(free));
}

// transfer() onto a finer mesh of the same box (each cell of the coarse mesh split in
// eight) reproduces a field of the basis' polynomial degree exactly: a nodal basis
// evaluates the old field at its new nodes (a node where an old one was keeps its value
// bit for bit), dg restricts each parent polynomial to its children. The field is
// quadratic for the quadratic bases (fem and fcm Hex20, dg k = 2) and affine for
// harmonic's trilinear cells.
TEST_P(Release, TransferToAFinerMeshReproducesTheBasisPolynomials) {
  const std::string block =
      GetParam() == "harmonic" ? "discretization/harmonic/convert/" : "discretization/" + GetParam() + "/";
  const auto build = [&](const std::string& resolution) {
    return load_scene(scene_file, {parse_scene_override(block + "resolution=" + resolution)});
  };
  const Scene coarse_scene = build("[10, 1, 1]"), fine_scene = build("[20, 2, 2]");
  const SceneGeometry geometry = load_scene_geometry(coarse_scene);
  const MethodDescription& method = cli::find_method(GetParam());
  const std::unique_ptr<MethodInstance> coarse = method.factory(coarse_scene, geometry);
  const std::unique_ptr<MethodInstance> fine = method.factory(fine_scene, geometry);
  const bool quadratic = GetParam() != "harmonic";
  const auto field = [quadratic](const Eigen::Vector3d& x) -> Eigen::Vector3d {
    const Eigen::Vector3d affine(0.01 * x.x() - 0.02 * x.z(), 0.03 * x.y() + 0.001, -0.02 * x.x() + 0.01 * x.y());
    return quadratic ? Eigen::Vector3d(
                           affine + Eigen::Vector3d(0.05 * x.x() * x.x(), 0.02 * x.x() * x.z(), 0.04 * x.y() * x.z()))
                     : affine;
  };
  const Eigen::VectorXd transferred = fine->transfer(*coarse, coarse->interpolate(field)).col(0);
  const Eigen::VectorXd expected = fine->interpolate(field);
  ASSERT_EQ(transferred.size(), expected.size());
  EXPECT_GT(expected.size(), coarse->interpolate(field).size());
  EXPECT_LT((transferred - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
}

// PETSc's solver sees the release as rows that couple again: its first-order coarse level
// (solver.p_multigrid: fem's and fcm's Hex20 here) builds its interpolation anew, and its
// restriction with it (PCMG keeps the first set-up's otherwise: CG then broke down after
// the release). The run matches CHOLMOD's five steps past the release.
TEST_P(Release, PetscFollowsTheReleaseAsCholmodDoes) {
  if (!petsc_available()) GTEST_SKIP() << "built without PETSc (-DALTFEM_PETSC=OFF)";
  const auto run = [&](const std::vector<std::string>& assignments) {
    std::vector<SceneOverride> overrides;
    for (const std::string& assignment : assignments) overrides.push_back(parse_scene_override(assignment));
    const Scene scene = load_scene(scene_file, overrides);
    const SceneGeometry geometry = load_scene_geometry(scene);
    Simulation simulation(scene, geometry, GetParam(), cli::find_method(GetParam()).factory);
    for (int step = 0; step < 25; ++step) simulation.integrator().step(simulation.state());
    simulation.apply(scene.events.front());
    for (int step = 0; step < 5; ++step) simulation.integrator().step(simulation.state());
    return Eigen::VectorXd(simulation.state().displacement);
  };
  const Eigen::VectorXd direct = run({});
  const Eigen::VectorXd iterative = run({"solver/linear=petsc", "solver/linear_tolerance=1e-12"});
  EXPECT_LT((iterative - direct).cwiseAbs().maxCoeff(), 1e-8 * direct.cwiseAbs().maxCoeff());
}

INSTANTIATE_TEST_SUITE_P(EveryMethod, Release, ::testing::Values("fem", "fcm", "dg", "harmonic"),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace altfem
