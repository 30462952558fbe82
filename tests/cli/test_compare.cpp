// `altfem run --set` and `altfem compare` end to end on a beam of a few elements: results.csv
// rows, report and plots, reuse of completed runs, a failing configuration reported with its
// exit code and message, and report.md redrawn from results.csv alone.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/cli/cli_support.hpp"

namespace altfem::test {
namespace {

std::string text_of(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(RunSet, OverridesAreAppliedAndBadOnesExitTwoNamingThem) {
  const auto out = fresh_directory("set");
  const auto scene = source_path("tests/cli/scenes/tiny_beam.json").string();
  const auto ok = run_altfem({"run", scene, "--method", "fem", "--out", (out / "a").string(), "--set",
                              "discretization/fem/resolution=[3,1,1]", "--set", "discretization/fem/element=tet4"});
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  const auto summary = nlohmann::json::parse(text_of(out / "a" / "summary.json"));
  EXPECT_EQ(summary["elements"]["tet4"], 3 * 6);  // Kuhn: six tetrahedra per grid cell
  for (const char* bad : {"material/model/x=1", "discretization/fem/resolution=[0,1,1]", "nokey"}) {
    const auto result = run_altfem({"run", scene, "--method", "fem", "--out", (out / "b").string(), "--set", bad});
    EXPECT_EQ(result.exit_code, 2) << bad;
    ASSERT_EQ(lines_of(result.err).size(), 1u) << result.err;
    const std::string named = std::string(bad).substr(0, std::string(bad).find('='));
    EXPECT_NE(result.err.find(named), std::string::npos) << result.err;
    EXPECT_FALSE(std::filesystem::exists(out / "b"));
  }
}

TEST(Compare, RunsReusesReportsFailuresAndRedrawsTheReportFromTheCsv) {
  const auto out = fresh_directory("compare");
  const std::vector<std::string> arguments{
      "compare", source_path("tests/cli/scenes/tiny_beam.json").string(), "--methods", "fem",
      "--sweep", "discretization/fem/resolution=[2,1,1],[4,1,1],[0,1,1]",
      "--reference", "fem:discretization/fem/element=hex20,discretization/fem/resolution=[4,1,1]",
      "--out", out.string()};
  const auto first = run_altfem(arguments);
  ASSERT_EQ(first.exit_code, 0) << first.err << first.out;
  EXPECT_NE(first.out.find("4 runs (0 reused, 1 failed)"), std::string::npos) << first.out;
  for (const char* file : {"results.csv", "report.md", "error_vs_time.png", "error_vs_dofs.png", "time_breakdown.png"})
    EXPECT_TRUE(std::filesystem::exists(out / file)) << file;

  const auto rows = lines_of(text_of(out / "results.csv"));
  ASSERT_EQ(rows.size(), 1u + 4u);  // header + 3 sweep values + the reference
  const std::string failed = rows[3];
  EXPECT_NE(failed.find("invalid input,2,"), std::string::npos) << failed;
  EXPECT_NE(failed.find("/discretization/fem/resolution/0: must be >= 1, got 0"), std::string::npos) << failed;
  EXPECT_NE(rows[4].find(",1,ok,0,"), std::string::npos) << "the reference is flagged: " << rows[4];
  const std::string report = text_of(out / "report.md");
  EXPECT_NE(report.find("## Failed runs"), std::string::npos);
  EXPECT_NE(report.find("must be >= 1, got 0"), std::string::npos);
  EXPECT_NE(report.find("Equal accuracy"), std::string::npos);

  // Nothing is rerun: the runs' folders are untouched.
  std::vector<std::filesystem::file_time_type> times;
  for (const auto& run : std::filesystem::directory_iterator(out / "runs"))
    times.push_back(std::filesystem::last_write_time(run.path() / "record.csv"));
  const auto second = run_altfem(arguments);
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_NE(second.out.find("4 runs (4 reused, 1 failed)"), std::string::npos) << second.out;
  std::size_t k = 0;
  for (const auto& run : std::filesystem::directory_iterator(out / "runs"))
    EXPECT_EQ(std::filesystem::last_write_time(run.path() / "record.csv"), times.at(k++));
  EXPECT_EQ(k, 4u);

  // report.md from results.csv alone, in a folder holding nothing else.
  const auto alone = fresh_directory("report-alone");
  std::filesystem::copy_file(out / "results.csv", alone / "results.csv");
  const std::string command = "/usr/bin/python3 " + source_path("scripts/plot_report.py").string() + " " +
                              (alone / "results.csv").string();
  ASSERT_EQ(std::system(command.c_str()), 0);
  EXPECT_EQ(text_of(alone / "report.md"), report);
  EXPECT_TRUE(std::filesystem::exists(alone / "error_vs_time.png"));
}

// The scene's compare/error sets the equal-accuracy table's target, kept in results.csv
// so that the report still regenerates from it alone.
TEST(Compare, TheScenesErrorTargetsTheEqualAccuracyTable) {
  const auto out = fresh_directory("compare-error");
  const auto result = run_altfem({"compare", source_path("tests/cli/scenes/tiny_beam_error.json").string(), "--out", out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err << result.out;
  const std::string report = text_of(out / "report.md");
  EXPECT_NE(report.find("## Equal accuracy: error ≤ 0.25"), std::string::npos) << report;
  const auto rows = lines_of(text_of(out / "results.csv"));
  EXPECT_NE(rows.at(0).find("report_error"), std::string::npos) << rows.at(0);
  const std::string command = "/usr/bin/python3 " + source_path("scripts/plot_report.py").string() + " " +
                              (out / "results.csv").string() + " --out " + (out / "again").string();
  ASSERT_EQ(std::system(command.c_str()), 0);
  EXPECT_EQ(text_of(out / "again" / "report.md"), report);
}

// A scene with an exact solution: each run's field errors join results.csv and the
// report gets their convergence plots (Hex8 fem from 2³ to 4³ cells: L2 falls ~4×, a
// rate of 2.6 in h ~ DOFs^(-1/3), which overstates h's ratio on such coarse grids).
TEST(Compare, FieldErrorsOfAnExactSolutionAreReported) {
  const auto out = fresh_directory("compare-field");
  const auto result = run_altfem({"compare", source_path("scenes/manufactured.json").string(), "--methods", "fem",
                                  "--sweep", "discretization/fem/resolution=[2,2,2],[4,4,4]", "--out", out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err << result.out;
  const std::string report = text_of(out / "report.md");
  EXPECT_NE(report.find("## Field errors against the exact solution"), std::string::npos) << report;
  EXPECT_TRUE(std::filesystem::exists(out / "field_l2_vs_dofs.png"));
  EXPECT_TRUE(std::filesystem::exists(out / "field_h1_vs_dofs.png"));
  const auto rate = report.find("fem hex8 L2 ");
  ASSERT_NE(rate, std::string::npos) << report;
  EXPECT_NEAR(std::stod(report.substr(rate + 12, 4)), 2.6, 0.3) << report.substr(rate, 40);
}

}  // namespace
}  // namespace altfem::test
