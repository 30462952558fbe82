// `altfem run` end to end on shipped scenes: the summary.json contract of docs/conventions.md,
// files read back by meshio, solver counts, and numerical failure (exit 3).
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "tests/cli/cli_support.hpp"

namespace altfem::test {
namespace {

TEST(Run, CantileverWritesTheSummaryContractAndReadableFiles) {
  const auto out = fresh_directory("cantilever") / "run";
  const auto result =
      run_altfem({"run", source_path("scenes/cantilever.json").string(), "--method", "fem", "--out", out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto summary = read_summary(out);
  for (const char* key : {"scene", "method", "options", "dofs", "elements", "quadrature_points", "timings_s", "counts",
                          "steps", "newton_iterations", "linear_iterations", "status", "surface"})
    EXPECT_TRUE(summary.contains(key)) << key;
  for (const char* key : {"setup", "quadrature", "assembly", "analysis", "factorisation", "solve", "total"})
    EXPECT_GE(summary["timings_s"][key].get<double>(), 0.0) << key;
  EXPECT_EQ(summary["status"], "ok");
  EXPECT_EQ(summary["method"], "fem");
  EXPECT_EQ(summary["options"]["discretization"]["fem"]["element"], "hex20");
  // A linear material: assembled and factorised once.
  EXPECT_EQ(summary["counts"]["analyses"], 1);
  EXPECT_EQ(summary["counts"]["factorisations"], 1);
  // CHOLMOD's operation count of one factorisation: at least one square root per free DOF.
  const int free_dofs = summary["dofs"].get<int>() - summary["constrained_dofs"].get<int>();
  EXPECT_GE(summary["environment"]["factorisation_blas_threads"]["flops"].get<double>(), free_dofs);
  EXPECT_TRUE(std::filesystem::exists(out / "log.txt"));
  const std::string check =
      "/usr/bin/python3 " + source_path("tests/cli/check_run_output.py").string() + " " + out.string();
  EXPECT_EQ(std::system(check.c_str()), 0) << "meshio disagrees with summary.json (see output above)";
}

TEST(Run, NewtonReportsOneAnalysisAndOneFactorisationPerIteration) {
  const auto out = fresh_directory("cube") / "run";
  const auto result =
      run_altfem({"run", source_path("scenes/cube_msh.json").string(), "--method", "fem", "--out", out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto summary = read_summary(out);
  const int iterations = summary["newton_iterations"];
  EXPECT_GT(iterations, 1) << "the scene should need several Newton iterations";
  EXPECT_EQ(summary["counts"]["analyses"], 1);
  EXPECT_EQ(summary["counts"]["factorisations"], iterations);
}

// Issue #35: Hex27 on the cantilever converged to a surface 6e-6 of the diagonal away from
// where Tet10 and Hex20 agree. Its default quadrature was too weak: the static potential
// energy, which nested conforming spaces can only lower (the minimum principle), rose
// from 10 × 1 × 1 to 20 × 2 × 2 cells. It must fall at every refinement.
TEST(Run, Hex27PotentialEnergyFallsUnderRefinementAsTheMinimumPrincipleDemands) {
  double previous = 0;
  for (const char* resolution : {"[10,1,1]", "[20,2,2]", "[40,4,4]"}) {
    const auto out = fresh_directory("hex27-energy") / resolution;
    const auto result = run_altfem({"run", source_path("scenes/cantilever.json").string(), "--method", "fem", "--set",
                                    "discretization/fem/element=hex27", "--set",
                                    std::string("discretization/fem/resolution=") + resolution, "--out", out.string()});
    ASSERT_EQ(result.exit_code, 0) << result.err;
    std::ifstream log(out / "log.txt");
    std::string line, last;
    while (std::getline(log, line))
      if (!line.empty() && line[0] != '#') last = line;
    std::istringstream fields(last);
    double value = 0, energy = 0;
    for (int column = 0; column < 7 && fields >> value; ++column) energy = value;
    if (previous != 0) {
      EXPECT_LT(energy, previous) << resolution;
    }
    previous = energy;
  }
}

TEST(Run, NewtonFailureExitsThreeNamingStepAndIteration) {
  const auto out = fresh_directory("newton-fails") / "run";
  const auto result = run_altfem(
      {"run", source_path("tests/cli/scenes/newton_fails.json").string(), "--method", "fem", "--out", out.string()});
  EXPECT_EQ(result.exit_code, 3) << result.err;
  const auto lines = lines_of(result.err);
  ASSERT_EQ(lines.size(), 1u) << result.err;
  EXPECT_NE(lines[0].find("step 1, Newton iteration"), std::string::npos) << lines[0];
  const auto summary = read_summary(out);
  EXPECT_EQ(summary["status"].get<std::string>().rfind("error: step 1", 0), 0u) << summary["status"];
}

// PETSc reads solver.petsc_options when the run builds its solver, before anything is
// written: an unknown type is bad input; a solve that runs out of iterations fails as
// any numerical failure does, with PETSc's reason.
#ifndef ALTFEM_HAVE_PETSC
#define SKIP_WITHOUT_PETSC() GTEST_SKIP() << "built without PETSc (-DALTFEM_PETSC=OFF)"
#else
#define SKIP_WITHOUT_PETSC() (void)0
#endif

TEST(Run, PetscOptionsWithAnUnknownTypeAreOneLineOfBadInputAndNoOutput) {
  SKIP_WITHOUT_PETSC();
  const auto out = fresh_directory("petsc-bad-options") / "run";
  const auto result =
      run_altfem({"run", source_path("scenes/cantilever.json").string(), "--method", "fem", "--set",
                  "solver/linear=petsc", "--set", "solver/petsc_options=-pc_type no_such_type", "--out", out.string()});
  EXPECT_EQ(result.exit_code, 2) << result.err;
  const auto lines = lines_of(result.err);
  ASSERT_EQ(lines.size(), 1u) << result.err;
  EXPECT_NE(lines[0].find("solver.petsc_options"), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("no_such_type"), std::string::npos) << lines[0];
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(Run, PetscOutOfIterationsExitsThreeWithPetscsReason) {
  SKIP_WITHOUT_PETSC();
  const auto out = fresh_directory("petsc-too-few-iterations") / "run";
  const auto result = run_altfem({"run", source_path("scenes/cantilever.json").string(), "--method", "fem", "--set",
                                  "solver/linear=petsc", "--set", "solver/linear_max_iterations=2", "--set",
                                  "solver/cutbacks=0", "--out", out.string()});
  EXPECT_EQ(result.exit_code, 3) << result.err;
  EXPECT_NE(result.err.find("DIVERGED_ITS after 2 iterations"), std::string::npos) << result.err;
}

// The warning about options PETSc did not use names the scene's own, not the gentler
// coarsening altfem sets for the first-order level's GAMG where one set-up serves several
// solves (here two load steps), which a coarse level of another type leaves unread, nor
// one that only a solve reads (-ksp_converged_reason).
TEST(Run, PetscsUnusedOptionsWarningNamesOnlyTheScenesOptions) {
  SKIP_WITHOUT_PETSC();
  const auto out = fresh_directory("petsc-unused-options") / "run";
  const auto result = run_altfem(
      {"run",
       source_path("scenes/cantilever.json").string(),
       "--method",
       "fem",
       "--set",
       "solver/linear=petsc",
       "--set",
       "discretization/fem/element=tet10",
       "--set",
       "discretization/fem/resolution=[20,2,2]",
       "--set",
       "time/load_steps=2",
       "--set",
       "solver/petsc_options=-ksp_type cg -pc_type gamg -mg_coarse_pc_type cholesky -pc_gamg_no_such_option 1 "
       "-ksp_converged_reason",
       "--set",
       "output/volume=false",
       "--set",
       "output/surface=false",
       "--out",
       out.string()});
  EXPECT_EQ(result.exit_code, 0) << result.err;
  const auto lines = lines_of(result.err);
  ASSERT_EQ(lines.size(), 1u) << result.err;
  EXPECT_NE(lines[0].find("did not use -pc_gamg_no_such_option"), std::string::npos) << lines[0];
  EXPECT_EQ(lines[0].find("aggressive_coarsening"), std::string::npos) << lines[0];
  EXPECT_EQ(lines[0].find("converged_reason"), std::string::npos) << lines[0];
}

TEST(Check, JsonOutputIsTheResolvedSceneAndGeometryFacts) {
  const auto result = run_altfem({"check", source_path("scenes/bunny.json").string(), "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto json = nlohmann::json::parse(result.out);
  EXPECT_EQ(json["geometry"]["kind"], "surface");
  EXPECT_EQ(json["geometry"]["vertices"], 1839);
  EXPECT_TRUE(json["geometry"]["closed"].get<bool>());
  EXPECT_GT(json["geometry"]["volume"].get<double>(), 0.0);
  EXPECT_TRUE(json["scene"].contains("solver")) << "defaults are resolved";
}

// `check` validates each scene and describes its geometry and what fem integrates. Building
// every method at the scene's own sizes took 73 s for all scenes (fcm alone 21 s on the
// twisting cylinder); that every method builds and runs on every scene is
// ShippedScene.RunsWithExitZeroAndFiniteOutput, at small sizes (test_shipped_scenes.cpp).
TEST(Check, EveryShippedSceneIsValid) {
  for (const auto& entry : std::filesystem::directory_iterator(source_path("scenes"))) {
    if (entry.path().extension() != ".json") continue;
    const auto result = run_altfem({"check", entry.path().string(), "--method", "fem"});
    EXPECT_EQ(result.exit_code, 0) << entry.path() << ": " << result.err;
    EXPECT_NE(result.out.find("fem: "), std::string::npos) << entry.path() << ": " << result.out;
  }
}

}  // namespace
}  // namespace altfem::test
