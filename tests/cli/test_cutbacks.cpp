// A Newton step that fails whole is retried in increments (solver.cutbacks; issue #35):
// a static load 1,000 times gravity on a Neo-Hookean cantilever, which one load step
// cannot reach, converges to the same equilibrium as ten explicit load steps.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli/cli_support.hpp"

namespace altfem::test {
namespace {

std::string log_text(const std::filesystem::path& out) {
  std::ifstream file(out / "log.txt");
  return {std::istreambuf_iterator<char>(file), {}};
}

TEST(Cutbacks, AStaticLoadOneStepCannotTakeConvergesInIncrementsToTheLoadSteppedEquilibrium) {
  const std::string scene = source_path("tests/cli/scenes/heavy_static_neo_hookean.json").string();
  const auto whole = fresh_directory("cutbacks-static") / "whole";
  const auto without = run_altfem({"run", scene, "--method", "fem", "--set", "solver/cutbacks=0", "--out",
                                   (fresh_directory("cutbacks-static") / "without").string()});
  ASSERT_EQ(without.exit_code, 3) << "the scene must fail without increments: " << without.err;

  const auto result = run_altfem({"run", scene, "--method", "fem", "--out", whole.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto summary = read_summary(whole);
  EXPECT_GE(summary["cutbacks"]["failed_attempts"].get<int>(), 1);
  EXPECT_LT(summary["cutbacks"]["smallest_increment"].get<double>(), 1.0);
  EXPECT_NE(log_text(whole).find("# cutback step 1: "), std::string::npos);

  const auto stepped = fresh_directory("cutbacks-static") / "stepped";
  const auto reference =
      run_altfem({"run", scene, "--method", "fem", "--set", "time/load_steps=10", "--out", stepped.string()});
  ASSERT_EQ(reference.exit_code, 0) << reference.err;
  // Hyperelastic equilibria do not depend on the load path: the potential energy and
  // the largest stress agree to Newton's tolerance.
  const std::vector<double> a = last_step_of_log(whole), b = last_step_of_log(stepped);
  ASSERT_EQ(a.size(), 8u);
  ASSERT_EQ(b.size(), 8u);
  EXPECT_NEAR(a[6], b[6], 1e-6 * std::abs(b[6])) << "total energy";
  EXPECT_NEAR(a[7], b[7], 1e-4 * b[7]) << "largest von Mises stress";
}

TEST(Cutbacks, ABackwardEulerStepTooLongForNewtonIsCutBackAndKeepsItsTime) {
  const std::string scene = source_path("tests/cli/scenes/soft_large_step.json").string();
  const auto without = run_altfem({"run", scene, "--method", "fem", "--set", "solver/cutbacks=0", "--out",
                                   (fresh_directory("cutbacks-dynamic") / "without").string()});
  ASSERT_EQ(without.exit_code, 3) << "the step must fail whole: " << without.err;
  const auto out = fresh_directory("cutbacks-dynamic") / "run";
  const auto result = run_altfem({"run", scene, "--method", "fem", "--out", out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto summary = read_summary(out);
  EXPECT_GE(summary["cutbacks"]["failed_attempts"].get<int>(), 1);
  EXPECT_EQ(summary["steps"].get<int>(), 2);
  const std::vector<double> last = last_step_of_log(out);
  ASSERT_EQ(last.size(), 8u);
  EXPECT_EQ(last[0], 2);
  EXPECT_DOUBLE_EQ(last[1], 20.0) << "the cut-back step ends at t + dt";
}

TEST(Cutbacks, AStepThatNeverConvergesNamesTheIncrementItReached) {
  const auto out = fresh_directory("cutbacks-fail") / "run";
  const auto result =
      run_altfem({"run", source_path("tests/cli/scenes/heavy_static_neo_hookean.json").string(), "--method", "fem",
                  "--set", "solver/cutbacks=1", "--set", "solver/max_iterations=2", "--out", out.string()});
  ASSERT_EQ(result.exit_code, 3) << result.err;
  EXPECT_NE(result.err.find("step 1: not converged in increments down to 2^-1 of the step (solver.cutbacks), "
                            "reached load factor "),
            std::string::npos)
      << result.err;
}

// corotated_linear has no barrier against inverting elements: the 100 Pa bar under its
// weight (stress 9.8 kPa) crushes elements past any step size, and cutbacks cannot reach
// t + dt. The failure names the time it reached and says why and what helps (issue #35).
TEST(Cutbacks, ACrushedCorotatedBarSaysItHasNoBarrierAgainstInversion) {
  const auto out = fresh_directory("cutbacks-corotated") / "run";
  const auto result = run_altfem({"run", source_path("tests/cli/scenes/soft_large_step.json").string(), "--method",
                                  "fem", "--set", "material/model=corotated_linear", "--out", out.string()});
  ASSERT_EQ(result.exit_code, 3) << result.err;
  EXPECT_NE(result.err.find("reached time "), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("'corotated_linear' has no barrier against inverting elements: use stable_neo_hookean"),
            std::string::npos)
      << result.err;
}

}  // namespace
}  // namespace altfem::test
