// A cube of side s clamped on one face under gravity (tests/cli/scenes/cube_under_gravity.json)
// is the unit cube scaled (issue #35, item 2): with the linear material the displacement
// scales as ρ g s² / E, so u / s² must equal the unit cube's, for s = 1 µm (strains of
// 1e-11, which forming F = I + ∇u used to round to a residual above Newton's tolerance)
// and s = 1,000 km, in every method; 1 µm cubes of Neo-Hookean, Stable Neo-Hookean and
// St. Venant–Kirchhoff are their 1 mm cubes scaled. Meshes scale exactly (ScaledGeometry, unit_scene).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "tests/cli/cli_support.hpp"

namespace altfem::test {
namespace {

// Runs the cube of side `side` (a JSON number) with `method`; returns its output folder.
std::filesystem::path run_cube(const std::string& method, const std::string& side,
                               const std::string& model = "linear") {
  const auto out = fresh_directory("scaled_cube_" + method + "_" + side + "_" + model) / "run";
  const auto result = run_altfem(
      {"run", source_path("tests/cli/scenes/cube_under_gravity.json").string(), "--method", method, "--out",
       out.string(), "--set", "geometry/shape/box/max=[" + side + "," + side + "," + side + "]", "--set",
       "boundary_conditions/0/region/box/min=[-" + side + ",-" + side + ",-" + side + "]", "--set",
       "boundary_conditions/0/region/box/max=[0," + side + "," + side + "]", "--set", "material/model=" + model});
  EXPECT_EQ(result.exit_code, 0) << side << ": " << result.err;
  return out;
}

class ScaledCube : public ::testing::TestWithParam<std::string> {};

TEST_P(ScaledCube, IsTheUnitCubeScaled) {
  const auto unit = run_cube(GetParam(), "1");
  for (const std::string side : {"1e-6", "1e6"}) {
    SCOPED_TRACE(side);
    const auto scaled = run_cube(GetParam(), side);
    const std::string check = "/usr/bin/python3 " + source_path("tests/cli/check_scaled_run.py").string() + " " +
                              unit.string() + " " + scaled.string() + " " + side + " 2";
    EXPECT_EQ(std::system(check.c_str()), 0) << "u / s² differs from the unit cube's (see output above)";
  }
  // The hyperelastic models at strains of 1e-11 keep the strains' digits: they take the
  // displacement gradient too (Material::pk1_at). Their 1 µm cube is their 1 mm cube
  // scaled, whose strains of 1e-8 leave 8 digits even to F = I + G and make the
  // nonlinearity 1e-8 (against the linear unit cube, dg's nonlinear path — the lifted
  // gradient — would differ as a discretization, not by round-off).
  for (const std::string model : {"neo_hookean", "stable_neo_hookean", "st_venant_kirchhoff"}) {
    SCOPED_TRACE(model);
    const auto millimetre = run_cube(GetParam(), "1e-3", model);
    const auto micrometre = run_cube(GetParam(), "1e-6", model);
    const std::string check = "/usr/bin/python3 " + source_path("tests/cli/check_scaled_run.py").string() + " " +
                              millimetre.string() + " " + micrometre.string() + " 1e-3 2";
    EXPECT_EQ(std::system(check.c_str()), 0) << "the 1 µm " << model << " cube is not its 1 mm cube scaled";
  }
}

INSTANTIATE_TEST_SUITE_P(EveryMethod, ScaledCube, ::testing::Values("fem", "fcm", "dg", "harmonic"));

}  // namespace
}  // namespace altfem::test
