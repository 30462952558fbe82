// Issue #22: failures that used to slip through the output contract
// (docs/conventions.md, "Command line and outputs"), each as a user meets it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli/cli_support.hpp"

namespace altfem::test {
namespace {

// No output file holds an `inf` or `nan` token.
void expect_no_non_finite_token(const std::filesystem::path& out) {
  for (const auto& entry : std::filesystem::directory_iterator(out)) {
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    for (const char* token : {"inf", "nan", "Infinity", "NaN"})
      EXPECT_EQ(text.str().find(token), std::string::npos) << entry.path() << " holds " << token;
  }
}

class ExplicitBlowUp : public testing::TestWithParam<std::string> {};

TEST_P(ExplicitBlowUp, StopsWithExitThreeNamingTheStepAndTheStabilityLimit) {
  const auto out = fresh_directory("explicit") / "run";
  const auto result = run_altfem(
      {"run", source_path("tests/cli/scenes/" + GetParam()).string(), "--method", "fem", "--out", out.string()});
  EXPECT_EQ(result.exit_code, 3) << result.err;
  EXPECT_NE(result.err.find("warning: time.dt"), std::string::npos) << "no up-front stability warning: " << result.err;
  EXPECT_NE(result.err.find("numerical failure: step "), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("explicit stability limit"), std::string::npos) << result.err;
  EXPECT_EQ(result.err.find("det F"), std::string::npos) << "blames det F: " << result.err;
  const auto summary = read_summary(out);
  EXPECT_NE(summary["status"].get<std::string>().find("error"), std::string::npos);
  EXPECT_GT(summary["facts"]["critical_time_step"].get<double>(), 0);
  expect_no_non_finite_token(out);
}

INSTANTIATE_TEST_SUITE_P(Issue22, ExplicitBlowUp,
                         testing::Values("explicit_blowup_snh.json", "explicit_blowup_linear.json"),
                         [](const auto& info) { return info.param.substr(0, info.param.size() - 5); });

void expect_one_line_exit_two(const CommandResult& result, const std::string& expected) {
  EXPECT_EQ(result.exit_code, 2) << result.err;
  const auto lines = lines_of(result.err);
  ASSERT_EQ(lines.size(), 1u) << result.err;
  EXPECT_EQ(lines[0].rfind("altfem: error: ", 0), 0u) << lines[0];
  EXPECT_NE(lines[0].find(expected), std::string::npos) << "expected '" << expected << "' in: " << lines[0];
}

TEST(Issue22, UnusableOutputFoldersAreBadInput) {
  const auto scene = source_path("scenes/cantilever.json").string();
  expect_one_line_exit_two(run_altfem({"run", scene, "--method", "fem", "--out", "/proc/altfem-test"}),
                           "--out /proc/altfem-test: cannot write");
  const auto file = fresh_directory("out-file") / "a-file";
  std::ofstream(file) << "x";
  expect_one_line_exit_two(run_altfem({"run", scene, "--method", "fem", "--out", file.string()}),
                           "is an existing file, expected a folder");
}

TEST(Issue22, SceneThatIsAFolderSaysSo) {
  const auto folder = fresh_directory("scene-folder");
  expect_one_line_exit_two(run_altfem({"run", folder.string(), "--method", "fem"}), "got a folder");
}

TEST(Issue22, MissingMethodIsOneLineWithThePrefix) {
  expect_one_line_exit_two(run_altfem({"run", source_path("scenes/cantilever.json").string()}), "--method is required");
}

TEST(Issue22, FailedRunCountsTheIterationsOfItsFailedStep) {
  const auto out = fresh_directory("newton-fails") / "run";
  const auto result = run_altfem(
      {"run", source_path("tests/cli/scenes/newton_fails.json").string(), "--method", "fem", "--out", out.string()});
  EXPECT_EQ(result.exit_code, 3);
  const auto summary = read_summary(out);
  EXPECT_GT(summary["newton_iterations"].get<long long>(), 0);
  EXPECT_GE(summary["newton_iterations"].get<long long>(), summary["counts"]["factorisations"].get<long long>());
}

TEST(Issue22, LbfgsReportsEvaluationsUnderItsOwnKey) {
  const auto out = fresh_directory("lbfgs") / "run";
  const auto result = run_altfem(
      {"run", source_path("tests/cli/scenes/lbfgs_cube.json").string(), "--method", "fem", "--out", out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto summary = read_summary(out);
  EXPECT_EQ(summary["newton_iterations"].get<long long>(), 0);
  EXPECT_GT(summary["lbfgs_evaluations"].get<long long>(), 0);
}

TEST(Issue22, StaticProblemWithoutSupportsIsBadInput) {
  const auto out = fresh_directory("no-supports") / "run";
  const auto result = run_altfem({"run", source_path("tests/cli/scenes/static_without_supports.json").string(),
                                  "--method", "fem", "--out", out.string()});
  expect_one_line_exit_two(result, "/boundary_conditions");
  EXPECT_FALSE(std::filesystem::exists(out));
}

// ν = 0.4999999 stalls Newton at the round-off floor of the assembled forces (λ/μ = 5e6):
// it stops there (issue #35) and says why and what helps against locking; the tip still
// bends as Euler–Bernoulli's beam, δ = ρ g A L⁴ / 8 E I, which does not depend on ν.
TEST(Issue22, NearIncompressibleStopsAtRoundOffAndSaysWhyAndWhatHelps) {
  const auto out = fresh_directory("incompressible") / "run";
  const auto result = run_altfem({"run", source_path("tests/cli/scenes/near_incompressible.json").string(), "--method",
                                  "fem", "--out", out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(read_summary(out)["round_off_stops"].get<int>(), 1);
  EXPECT_NE(result.err.find("ill-conditioned"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("higher-order element"), std::string::npos) << result.err;
  const double beam = 1000 * 9.81 * 0.01 / (8 * 1e9 * std::pow(0.1, 4) / 12);
  const std::string check = "/usr/bin/python3 " + source_path("tests/cli/check_mean_displacement.py").string() + " " +
                            out.string() + " 1 -1 -1 1 1 1 2 " + std::to_string(-1.0 * beam) + " " +
                            std::to_string(-0.9 * beam);
  EXPECT_EQ(std::system(check.c_str()), 0) << "the tip is not within 10% of the beam's " << beam << " m";
}

// fem cuts exactly by default (issue #33): a plane 1e-10 m past a grid plane leaves a piece
// of a billionth of its element, and a node copy on it gets no mass at all. The run stops
// with exit 3 and names the key that helps; with it the same cut runs.
TEST(Issue22, AFemCutTooThinForItsMassNamesTheStabilization) {
  const auto scene = source_path("tests/verify/events/scenes/cantilever_cut.json").string();
  const std::vector<std::string> thin_cut = {"--set", "events/0/cut/plane/point=[0.5000000001,0,0]", "--set",
                                             "time/steps=6"};
  const auto out = fresh_directory("thin-fem-cut");
  std::vector<std::string> arguments = {"run", scene, "--method", "fem", "--out", (out / "exact").string()};
  arguments.insert(arguments.end(), thin_cut.begin(), thin_cut.end());
  const auto exact = run_altfem(arguments);
  EXPECT_EQ(exact.exit_code, 3) << exact.err;
  EXPECT_NE(exact.err.find("not positive"), std::string::npos) << exact.err;
  EXPECT_NE(exact.err.find("discretization.fem.cut_stabilization"), std::string::npos) << exact.err;
  arguments[5] = (out / "stabilised").string();
  arguments.insert(arguments.end(), {"--set", "discretization/fem/cut_stabilization=1e-6"});
  const auto stabilised = run_altfem(arguments);
  EXPECT_EQ(stabilised.exit_code, 0) << stabilised.err;
}

}  // namespace
}  // namespace altfem::test
