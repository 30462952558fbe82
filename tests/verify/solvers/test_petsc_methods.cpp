// solver.linear "petsc" on the methods' own systems (issue #37, step 1), the cantilever
// of scenes/cantilever.json (1 × 0.1 × 0.1 m, clamped at x = 0, gravity):
//   - every method's CG + GAMG solution is its CHOLMOD solution;
//   - the rigid-body modes as GAMG's near-null space (rigid_body_modes: each method's own
//     basis, dg's monomials included) cut the iterations: aggregation that knows only
//     translations builds coarse spaces that cannot rotate (Vaněk, Mandel & Brezina 1996);
//   - with them, CG + GAMG on fem Hex8 reaches 1e-8 in at most 30 iterations and grows by
//     at most 20% under one 8× refinement: the issue's targets, the flat iteration counts
//     of smoothed aggregation (deal.II step-40's AMG), where step-17's PETSc ILU went
//     27 → 261;
//   - on quadratic elements, GAMG on the first-order space inside (solver.p_multigrid)
//     meets the same targets on fem Hex20; on dg's vertex space (one function per mesh
//     vertex, each cell its affine fit) it meets them on dg k = 1 and takes fewer
//     iterations than on the whole space for k = 1 and k = 2;
//   - on fcm's cut cells (the half-ball), the method's Additive Schwarz as the smoother of
//     GAMG's finest level (solver.method_smoother) cuts its iterations tenfold: cut cells
//     leave functions with a sliver of material that GAMG's point smoother and aggregates
//     do not reduce, and the Schwarz blocks invert them;
//   - with the face ghost penalty instead, on an adaptively refined grid (hanging nodes in
//     both spaces), each solve takes at most 30 iterations on average.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "shared/scene/scene_geometry.hpp"
#include "shared/scene/scene_override.hpp"
#include "shared/simulation/run_simulation.hpp"
#include "shared/simulation/simulation.hpp"
#include "shared/solve/petsc_solver.hpp"
#include "tests/support/static_solve.hpp"

namespace altfem {
namespace {

struct Solved {
  Eigen::VectorXd displacement;
  long iterations = 0;
};

// Static equilibrium of scenes/`name`.json by `method` with the scene changed by `assignments`.
Solved solve_scene(const std::string& name, const std::string& method, const std::vector<std::string>& assignments) {
  std::vector<SceneOverride> overrides;
  for (const std::string& assignment : assignments) overrides.push_back(parse_scene_override(assignment));
  const Scene scene = load_scene(std::filesystem::path(ALTFEM_SOURCE_DIR) / "scenes" / (name + ".json"), overrides);
  const SceneGeometry geometry = load_scene_geometry(scene);
  Simulation simulation(scene, geometry, method, test::registered_method(method).factory);
  simulation.integrator().step(simulation.state());
  return {simulation.state().displacement, simulation.linear_statistics().iterations};
}

Solved solve_cantilever(const std::string& method, const std::vector<std::string>& assignments) {
  return solve_scene("cantilever", method, assignments);
}

class PetscOnEveryMethod : public ::testing::TestWithParam<std::string> {
protected:
  void SetUp() override {
    if (!petsc_available()) GTEST_SKIP() << "built without PETSc (-DALTFEM_PETSC=OFF)";
  }
};

// CG stops at a relative residual of 1e-12; with condition numbers below 1e5 at these
// sizes that bounds the relative error by 1e-7.
TEST_P(PetscOnEveryMethod, CgWithGamgGivesTheDirectSolution) {
  const Solved direct = solve_cantilever(GetParam(), {});
  const Solved iterative = solve_cantilever(GetParam(), {"solver/linear=petsc", "solver/linear_tolerance=1e-12"});
  EXPECT_GT(iterative.iterations, 0);
  EXPECT_LT((iterative.displacement - direct.displacement).norm(), 1e-7 * direct.displacement.norm());
}

TEST_P(PetscOnEveryMethod, RigidBodyModesCutGamgsIterations) {
  const std::vector<std::string> petsc{"solver/linear=petsc", "solver/linear_tolerance=1e-8"};
  std::vector<std::string> translations_only = petsc;
  translations_only.push_back("solver/rigid_body_modes=false");
  const long with_modes = solve_cantilever(GetParam(), petsc).iterations;
  const long without = solve_cantilever(GetParam(), translations_only).iterations;
  EXPECT_LT(with_modes, without);
}

INSTANTIATE_TEST_SUITE_P(EveryMethod, PetscOnEveryMethod, ::testing::Values("fem", "fcm", "dg", "harmonic"),
                         [](const auto& info) { return info.param; });

TEST(PetscGamg, FemHex8IterationsStayFlatUnderRefinement) {
  if (!petsc_available()) GTEST_SKIP() << "built without PETSc (-DALTFEM_PETSC=OFF)";
  const auto iterations = [](const std::string& resolution) {
    return solve_cantilever("fem", {"solver/linear=petsc", "solver/linear_tolerance=1e-8",
                                    "discretization/fem/element=hex8", "discretization/fem/resolution=" + resolution})
        .iterations;
  };
  const long coarse = iterations("[20,2,2]");
  const long fine = iterations("[40,4,4]");
  EXPECT_LE(coarse, 30);
  EXPECT_LE(fine, 30);
  EXPECT_LE(fine, 1.2 * coarse);
}

// Quadratic elements: GAMG aggregates a Hex20 node's neighbourhood, not a mesh
// neighbourhood, and took 59 iterations at both sizes; on the first-order space inside
// (solver.p_multigrid: a two-level multigrid, Jacobi-Chebyshev on the Hex20 level) it
// meets the targets Hex8 meets.
TEST(PetscGamg, FemHex20OnItsFirstOrderSpaceMeetsTheIterationTargets) {
  if (!petsc_available()) GTEST_SKIP() << "built without PETSc (-DALTFEM_PETSC=OFF)";
  const auto iterations = [](const std::string& resolution, bool p_multigrid) {
    return solve_cantilever("fem", {"solver/linear=petsc", "solver/linear_tolerance=1e-8",
                                    "discretization/fem/element=hex20", "discretization/fem/resolution=" + resolution,
                                    std::string("solver/p_multigrid=") + (p_multigrid ? "true" : "false")})
        .iterations;
  };
  const long coarse = iterations("[20,2,2]", true);
  const long fine = iterations("[40,4,4]", true);
  EXPECT_LE(coarse, 30);
  EXPECT_LE(fine, 30);
  EXPECT_LE(fine, 1.2 * coarse);
  EXPECT_LT(fine, iterations("[40,4,4]", false));
}

// dg: a DG "node" is a cell's whole monomial block, and GAMG on the whole space took 35-38
// iterations on k = 1 and 71-87 on k = 2; on the vertex space (dg/multigrid_coarse_space.hpp:
// one function per mesh vertex, each cell its affine fit, a first-order operator for GAMG)
// k = 1 meets the targets (18 and 29) and k = 2 takes fewer (34 against 87 on 20 × 2 × 2,
// its level coarsened gently).
TEST(PetscGamg, DgDegreeOneOnItsVertexSpaceMeetsTheIterationTarget) {
  if (!petsc_available()) GTEST_SKIP() << "built without PETSc (-DALTFEM_PETSC=OFF)";
  const auto solve = [](const std::string& resolution, bool p_multigrid) {
    return solve_cantilever("dg", {"solver/linear=petsc", "solver/linear_tolerance=1e-8", "discretization/dg/degree=1",
                                   "discretization/dg/resolution=" + resolution,
                                   std::string("solver/p_multigrid=") + (p_multigrid ? "true" : "false")});
  };
  const Solved coarse = solve("[20,2,2]", true);
  const Solved fine = solve("[40,4,4]", true);
  EXPECT_LE(coarse.iterations, 30);
  EXPECT_LE(fine.iterations, 30);
  EXPECT_LT(fine.iterations, solve("[40,4,4]", false).iterations);
  const Solved direct = solve_cantilever("dg", {"discretization/dg/degree=1", "discretization/dg/resolution=[40,4,4]"});
  EXPECT_LT((fine.displacement - direct.displacement).norm(), 1e-6 * direct.displacement.norm());
}

// A nonlinear material (dg's tabulated path, its Hessian set up anew at every Newton
// iteration) works on the vertex space too: the Neo-Hookean cantilever's two Newton solves
// took 44 iterations on k = 1 against 133 on the whole space.
TEST(PetscGamg, DgWithANonlinearMaterialWorksOnItsVertexSpaceToo) {
  if (!petsc_available()) GTEST_SKIP() << "built without PETSc (-DALTFEM_PETSC=OFF)";
  const std::vector<std::string> neo_hookean{"material/model=neo_hookean", "discretization/dg/degree=1",
                                             "discretization/dg/resolution=[20,2,2]"};
  const auto solve = [&](std::vector<std::string> settings) {
    settings.insert(settings.end(), neo_hookean.begin(), neo_hookean.end());
    return solve_cantilever("dg", settings);
  };
  const Solved on_vertices = solve({"solver/linear=petsc", "solver/linear_tolerance=1e-10"});
  EXPECT_LT(on_vertices.iterations,
            solve({"solver/linear=petsc", "solver/linear_tolerance=1e-10", "solver/p_multigrid=false"}).iterations);
  const Solved direct = solve({});
  EXPECT_LT((on_vertices.displacement - direct.displacement).norm(), 1e-6 * direct.displacement.norm());
}

TEST(PetscGamg, DgDegreeTwoOnItsVertexSpaceTakesFewerIterations) {
  if (!petsc_available()) GTEST_SKIP() << "built without PETSc (-DALTFEM_PETSC=OFF)";
  const std::vector<std::string> degree_two{"discretization/dg/degree=2", "discretization/dg/resolution=[20,2,2]"};
  std::vector<std::string> two_level = degree_two;
  for (const char* setting : {"solver/linear=petsc", "solver/linear_tolerance=1e-12"}) two_level.push_back(setting);
  std::vector<std::string> whole = two_level;
  whole.push_back("solver/p_multigrid=false");
  const Solved on_vertices = solve_cantilever("dg", two_level);
  const Solved on_whole = solve_cantilever("dg", whole);
  EXPECT_LT(on_vertices.iterations, on_whole.iterations);
  const Solved direct = solve_cantilever("dg", degree_two);
  EXPECT_LT((on_vertices.displacement - direct.displacement).norm(), 1e-7 * direct.displacement.norm());
}

// Where one GAMG set-up serves several solves (a linear material's constant Hessian over
// load steps or time steps), GAMG coarsens its finest level without MIS-2 on the squared
// graph: a dearer set-up, paid once, for fewer iterations at every solve (Hex8's 20 × 2 × 2
// cantilever 16 against 28); a single solve, or a Hessian that changes, keeps the default.
// fem's first-order level coarsens gently even for one solve (CoarseSpace::coarsen_gently):
// on the Tet10 cantilever it meets the issue's 30, which aggressive coarsening (39) misses.
TEST(PetscGamg, OneSetUpForSeveralSolvesCoarsensGentlyAndTet10sFirstOrderLevelAlways) {
  if (!petsc_available()) GTEST_SKIP() << "built without PETSc (-DALTFEM_PETSC=OFF)";
  const auto with = [](const std::string& element, std::vector<std::string> settings) {
    for (const std::string& setting :
         {"discretization/fem/element=" + element, std::string("discretization/fem/resolution=[20,2,2]")})
      settings.push_back(setting);
    return settings;
  };
  const auto aggressive = [&](const std::vector<std::string>& settings) {
    std::vector<SceneOverride> overrides;
    for (const std::string& assignment : with("hex8", settings)) overrides.push_back(parse_scene_override(assignment));
    const Scene scene = load_scene(std::filesystem::path(ALTFEM_SOURCE_DIR) / "scenes/cantilever.json", overrides);
    const SceneGeometry geometry = load_scene_geometry(scene);
    const auto method = test::registered_method("fem").factory(scene, geometry);
    return linear_solver_options(scene, *method).aggressive_coarsening;
  };
  EXPECT_TRUE(aggressive({"solver/linear=petsc"}));
  EXPECT_FALSE(aggressive({"solver/linear=petsc", "time/load_steps=2"}));
  EXPECT_FALSE(aggressive({"solver/linear=petsc", R"(time={"steps": 10, "dt": 0.001})"}));
  EXPECT_TRUE(aggressive({"solver/linear=petsc", "time/load_steps=2", "material/model=\"neo_hookean\""}));

  const std::vector<std::string> petsc{"solver/linear=petsc", "solver/linear_tolerance=1e-8"};
  std::vector<std::string> two_steps = petsc;
  two_steps.push_back("time/load_steps=2");
  const Solved gentle = solve_cantilever("fem", with("hex8", two_steps));  // the first load step, half the load
  EXPECT_LT(gentle.iterations, solve_cantilever("fem", with("hex8", petsc)).iterations);
  const Solved direct = solve_cantilever("fem", with("hex8", {"time/load_steps=2"}));
  EXPECT_LT((gentle.displacement - direct.displacement).norm(), 1e-6 * direct.displacement.norm());

  std::vector<std::string> coarse_aggressive = petsc;
  coarse_aggressive.push_back(
      "solver/petsc_options=-ksp_type cg -pc_type gamg -mg_coarse_pc_gamg_aggressive_coarsening 1");
  const long tet10 = solve_cantilever("fem", with("tet10", petsc)).iterations;
  EXPECT_LE(tet10, 30);
  EXPECT_LT(tet10, solve_cantilever("fem", with("tet10", coarse_aggressive)).iterations);
}

TEST(PetscGamg, FcmsSchwarzBlocksSmoothingTheFinestLevelCutItsIterationsTenfold) {
  if (!petsc_available()) GTEST_SKIP() << "built without PETSc (-DALTFEM_PETSC=OFF)";
  const std::vector<std::string> defaults{"solver/linear=petsc", "solver/linear_tolerance=1e-8",
                                          "discretization/fcm/resolution=[4, 4, 2]"};
  std::vector<std::string> gamg = defaults;  // GAMG on the whole Hex20 space
  gamg.push_back("solver/p_multigrid=false");
  std::vector<std::string> gamg_alone = gamg;
  gamg_alone.push_back("solver/method_smoother=false");
  const Solved smoothed = solve_scene("manufactured_half_ball", "fcm", gamg);
  const Solved alone = solve_scene("manufactured_half_ball", "fcm", gamg_alone);
  EXPECT_LE(10 * smoothed.iterations, alone.iterations)
      << "with the Schwarz blocks " << smoothed.iterations << ", without " << alone.iterations;
  // The default: GAMG on the first-order space below the Schwarz-smoothed Hex20 level
  // takes no more.
  const Solved two_level = solve_scene("manufactured_half_ball", "fcm", defaults);
  EXPECT_LE(two_level.iterations, smoothed.iterations);
  const Solved direct = solve_scene("manufactured_half_ball", "fcm", {"discretization/fcm/resolution=[4, 4, 2]"});
  EXPECT_LT((smoothed.displacement - direct.displacement).norm(), 1e-6 * direct.displacement.norm());
  EXPECT_LT((two_level.displacement - direct.displacement).norm(), 1e-6 * direct.displacement.norm());
}

// The face ghost penalty instead of the stabilisation leaves no function of tiny energy for
// the smoother to miss, and on an adaptively refined grid the first-order space keeps
// hanging nodes of its own: two error-indicator cycles on the half-ball's Hex20 cells, each
// solve at most 30 iterations on average, fewer than with GAMG on the whole space, and the
// same solution.
TEST(PetscGamg, FcmsGhostPenaltyMeetsTheTargetOnAnAdaptivelyRefinedGrid) {
  if (!petsc_available()) GTEST_SKIP() << "built without PETSc (-DALTFEM_PETSC=OFF)";
  const auto run = [](bool p_multigrid) {
    std::vector<SceneOverride> overrides;
    for (
        const std::string& assignment : std::vector<std::string>{
            "discretization/fcm={\"resolution\": [4, 4, 2], \"ghost_penalty\": 1e-3, \"stabilization\": 0}",
            R"(events=[{"time": 0, "refine": {"criterion": "error_indicator", "fraction": 0.5, "max_level": 3, "cycles": 2}}])",
            "solver/linear=petsc", "solver/linear_tolerance=1e-8",
            std::string("solver/p_multigrid=") + (p_multigrid ? "true" : "false"),
            R"(output={"volume": false, "surface": false})"})
      overrides.push_back(parse_scene_override(assignment));
    const Scene scene =
        load_scene(std::filesystem::path(ALTFEM_SOURCE_DIR) / "scenes/manufactured_half_ball.json", overrides);
    const std::filesystem::path output = std::filesystem::path(ALTFEM_BINARY_DIR) / "verify_ghost_penalty_refined";
    const nlohmann::json summary =
        run_simulation(scene, load_scene_geometry(scene), "fcm", test::registered_method("fcm"), output, 0.0);
    std::filesystem::remove_all(output);
    return summary;
  };
  const nlohmann::json two_level = run(true), whole = run(false);
  ASSERT_EQ(two_level["status"], "ok") << two_level.dump();
  ASSERT_EQ(whole["status"], "ok") << whole.dump();
  EXPECT_GT(two_level["events"].at(1)["facts"]["hanging_nodes"].get<int>(), 0);
  const long iterations = two_level["linear_iterations"].get<long>();
  EXPECT_LE(iterations, 30 * two_level["newton_iterations"].get<long>());
  EXPECT_LT(iterations, whole["linear_iterations"].get<long>());
  EXPECT_NEAR(two_level["field_errors"]["relative_h1_seminorm"].get<double>(),
              whole["field_errors"]["relative_h1_seminorm"].get<double>(), 1e-6);
}

// On fcm's Hex8 cells GAMG is the whole multigrid and the Schwarz blocks smooth its finest
// level: where eight small cut cells' blocks share a node, S A has an eigenvalue of at
// least 8 that PETSc's Chebyshev estimate (3.0 on the 8 × 8 × 4 grid) missed, and CG
// broke with an indefinite preconditioner; the bounds now cover the blocks' overlap.
TEST(PetscGamg, FcmsHex8SchwarzSmoothedLevelKeepsCgDefinite) {
  if (!petsc_available()) GTEST_SKIP() << "built without PETSc (-DALTFEM_PETSC=OFF)";
  const std::vector<std::string> hex8{"discretization/fcm/cell=hex8", "discretization/fcm/resolution=[8, 8, 4]"};
  std::vector<std::string> petsc = hex8;
  petsc.insert(petsc.end(), {"solver/linear=petsc", "solver/linear_tolerance=1e-10"});
  const Solved smoothed = solve_scene("manufactured_half_ball", "fcm", petsc);
  const Solved direct = solve_scene("manufactured_half_ball", "fcm", hex8);
  EXPECT_GT(smoothed.iterations, 0);
  EXPECT_LT((smoothed.displacement - direct.displacement).norm(), 1e-8 * direct.displacement.norm());
}

}  // namespace
}  // namespace altfem
