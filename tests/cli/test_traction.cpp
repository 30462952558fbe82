// Surface loads end to end (`loads.traction`): a static traction benchmark and a
// dynamic run with a ramped pressure write finite, readable output; a load region that
// holds no triangle of the loaded surface is bad input for `check` and `run` alike.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "tests/cli/cli_support.hpp"

namespace altfem::test {
namespace {

void expect_finite_run(const std::string& scene, const std::string& name) {
  const auto out = fresh_directory(name) / "run";
  const auto result = run_altfem({"run", source_path(scene).string(), "--method", "fem", "--out", out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::string check =
      "/usr/bin/python3 " + source_path("tests/cli/check_run_output.py").string() + " " + out.string();
  EXPECT_EQ(std::system(check.c_str()), 0) << "meshio disagrees with summary.json, or a field is not finite";
  // log.txt: step time dofs iterations linear_iterations residual total_energy max_von_mises.
  std::ifstream log(out / "log.txt");
  int steps = 0;
  for (std::string line; std::getline(log, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    double value = 0, von_mises = 0;
    for (int i = 0; i < 7; ++i) fields >> value;
    fields >> von_mises;
    EXPECT_TRUE(std::isfinite(von_mises) && von_mises > 0) << "the load stresses the body: " << line;
    ++steps;
  }
  EXPECT_GE(steps, 1);
}

TEST(Traction, CookMembraneRunsWithFem) { expect_finite_run("scenes/cook_membrane.json", "cook-membrane"); }

TEST(Traction, RampedPressureRunsDynamically) {
  expect_finite_run("tests/cli/scenes/pressure_ramp.json", "pressure-ramp");
}

TEST(Traction, RegionHoldingNoTriangleIsBadInput) {
  const auto scene = source_path("tests/cli/scenes/traction_selects_no_triangle.json");
  const auto out = fresh_directory("traction-no-triangle") / "run";
  for (const auto& result : {run_altfem({"check", scene.string()}),
                             run_altfem({"run", scene.string(), "--method", "fem", "--out", out.string()})}) {
    EXPECT_EQ(result.exit_code, 2) << result.err;
    const auto lines = lines_of(result.err);
    ASSERT_EQ(lines.size(), 1u) << result.err;
    EXPECT_NE(lines[0].find("/loads/traction/0/region: holds the centroid of no triangle"), std::string::npos)
        << lines[0];
  }
  EXPECT_FALSE(std::filesystem::exists(out)) << "a rejected run left " << out;
}

}  // namespace
}  // namespace altfem::test
