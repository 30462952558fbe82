// A plate 1 m × 1 m × 1 mm, clamped along x = 0, under its own weight (issue #35, item 2;
// tests/cli/scenes/thin_plate.json) with every method's defaults. Its bending cancels the
// element forces to ~0.1–0.7 ε ‖|K||u|‖, a hundred times the load tolerance: Newton used
// to iterate to its limit (fem) or fail its line search (fcm, dg). Now it stops at that
// round-off floor, and the free edge's mean deflection lies between the two limits of
// linear plate theory: the cantilever plate in cylindrical bending (D = E t³ / 12(1 − ν²),
// w = q L⁴ / 8D) and the beam of the same width (E t³ / 12), q = ρ g t.
// harmonic's trilinear cells, 31 times wider than thick, lock in bending: it must say so.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli/cli_support.hpp"

namespace altfem::test {
namespace {

class ThinPlate : public ::testing::TestWithParam<std::string> {};

TEST_P(ThinPlate, BendsBetweenCylindricalBendingAndTheBeam) {
  const std::string method = GetParam();
  const auto out = fresh_directory("thin_plate_" + method) / "run";
  const auto result = run_altfem(
      {"run", source_path("tests/cli/scenes/thin_plate.json").string(), "--method", method, "--out", out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  std::ifstream summary_file(out / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(summary_file);
  EXPECT_EQ(summary["status"], "ok");
  const double E = 1e9, nu = 0.3, rho = 1000, g = 9.81, t = 1e-3, L = 1;
  const double beam = 12 * rho * g * t * L * L * L * L / (8 * E * t * t * t);
  const double cylindrical = (1 - nu * nu) * beam;
  // The free edge's mean z displacement, read back from the surface frame.
  const std::string check = "/usr/bin/python3 " + source_path("tests/cli/check_mean_displacement.py").string() + " " +
                            out.string() + " 1 -1 -1 1 2 2 2 " + std::to_string(-1.01 * beam) + " " +
                            std::to_string(-0.99 * cylindrical);
  EXPECT_EQ(std::system(check.c_str()), 0)
      << "the free edge's deflection is outside [" << cylindrical << ", " << beam << "] m (see output above)";
}

INSTANTIATE_TEST_SUITE_P(EveryConformingOrHigherOrderMethod, ThinPlate, ::testing::Values("fem", "fcm", "dg"));

TEST(ThinPlate, HarmonicSaysItsFlatTrilinearCellsLockInBending) {
  const auto out = fresh_directory("thin_plate_harmonic") / "run";
  const auto result = run_altfem(
      {"run", source_path("tests/cli/scenes/thin_plate.json").string(), "--method", "harmonic", "--out", out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.err.find("lock in bending"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace altfem::test
