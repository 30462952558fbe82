// `altfem check`: the method blocks it resolves and the volume each method integrates.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "tests/cli/cli_support.hpp"

namespace altfem::test {
namespace {

// The shipped hollow cylinder (r 0.07–0.1, height 0.5) with its default Tet10 cells, curved or not.
std::filesystem::path cylinder_scene(bool curved) {
  const auto folder = fresh_directory(std::string("check-cylinder-") + (curved ? "curved" : "straight"));
  std::ifstream in(source_path("scenes/hollow_cylinder.json"));
  nlohmann::json scene = nlohmann::json::parse(in);
  scene["discretization"] = {{"fem", {{"element", "tet10"}, {"max_cell_size", 0.025}, {"curved", curved}}}};
  scene.erase("compare");
  const auto file = folder / "cylinder.json";
  std::ofstream(file) << scene.dump();
  return file;
}

double integrated_volume(bool curved) {
  const CommandResult result = run_altfem({"check", cylinder_scene(curved).string(), "--method", "fem", "--json"});
  EXPECT_EQ(result.exit_code, 0) << result.err;
  return nlohmann::json::parse(result.out)["methods"]["fem"]["integrated_volume"].get<double>();
}

TEST(Check, ReportsTheIsoparametricVolumeOfACurvedMesh) {
  const double exact = std::numbers::pi * (0.1 * 0.1 - 0.07 * 0.07) * 0.5;
  const double straight = std::abs(integrated_volume(false) / exact - 1);
  const double curved = std::abs(integrated_volume(true) / exact - 1);
  std::printf("volume error: straight-sided %.2e, curved %.2e\n", straight, curved);
  // Both meshes have the same vertices, so a straight-sided volume would be the same
  // for both. Chords of the circles lose ~h²/(12 r²) of the area; curved quadratic
  // edges recover most of it. What is left is Mesh_3's rounding of the sharp rims
  // (its features are not protected: issue #21, item 5).
  EXPECT_GT(straight, 5e-3);
  EXPECT_LT(curved, straight / 3);
}

TEST(Check, ResolvesEveryMethodBlockWithoutMethod) {
  const CommandResult result = run_altfem({"check", source_path("scenes/cantilever.json").string(), "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json report = nlohmann::json::parse(result.out);
  for (const auto& [name, facts] : report["methods"].items()) {
    SCOPED_TRACE(name);
    EXPECT_TRUE(report["scene"]["discretization"].contains(name));
    EXPECT_GT(facts["dofs"].get<long long>(), 0);
    EXPECT_LT(std::abs(facts["volume_difference"].get<double>()), 1e-10);  // a box: every method integrates it exactly
  }
  EXPECT_TRUE(report["methods"].contains("fem"));
}

// Issue #35: a hexahedral volume mesh as the geometry made `check` fail for every
// method, since fcm refused it; fcm now splits its cells into tetrahedra
// (tetrahedra_of_hexahedra) and every method integrates the cube's volume exactly.
TEST(Check, AHexahedralGeometryMeshServesEveryMethod) {
  const CommandResult result =
      run_altfem({"check", source_path("tests/cli/scenes/hexahedral_geometry_mesh.json").string(), "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json report = nlohmann::json::parse(result.out);
  EXPECT_TRUE(report["methods"].contains("fcm"));
  for (const auto& [name, facts] : report["methods"].items()) {
    SCOPED_TRACE(name);
    EXPECT_LT(std::abs(facts["volume_difference"].get<double>()), 1e-10);
  }
}

// Issue #35: `check` reports per method. dg's stitched embedding needs a converted mesh,
// so on a sliced cantilever dg cannot run while the others can: they are reported, dg's
// reason is the one line on stderr that `run --method dg` would print, and the exit code
// says the scene is not valid for every method. A scene no method can run is one failure.
TEST(Check, AMethodThatCannotRunTheSceneDoesNotHideTheOthers) {
  std::ifstream in(source_path("scenes/cantilever.json"));
  nlohmann::json scene = nlohmann::json::parse(in);
  scene.erase("compare");
  scene["discretization"]["dg"] = {{"mesh", "slice"}, {"embedding", "stitched"}};
  const auto file = fresh_directory("check-per-method") / "scene.json";
  std::ofstream(file) << scene.dump();
  const CommandResult result = run_altfem({"check", file.string(), "--json"});
  EXPECT_EQ(result.exit_code, 2);
  const auto lines = lines_of(result.err);
  ASSERT_EQ(lines.size(), 1u) << result.err;
  EXPECT_NE(lines[0].find("/discretization/dg/embedding"), std::string::npos) << lines[0];
  const nlohmann::json report = nlohmann::json::parse(result.out);
  for (const char* can : {"fem", "fcm", "harmonic"}) {
    SCOPED_TRACE(can);
    EXPECT_GT(report["methods"][can]["dofs"].get<long long>(), 0);
  }
  EXPECT_EQ(report["methods"]["dg"]["error"].get<std::string>(), lines[0]);

  const CommandResult only_dg = run_altfem({"check", file.string(), "--method", "dg", "--json"});
  EXPECT_EQ(only_dg.exit_code, 2);
  EXPECT_TRUE(only_dg.out.empty()) << only_dg.out;
  EXPECT_EQ(lines_of(only_dg.err), lines);
}

TEST(Check, UnknownMethodIsBadInput) {
  const CommandResult result = run_altfem({"check", source_path("scenes/cantilever.json").string(), "--method", "fxm"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("--method: method 'fxm' is not available in this build"), std::string::npos) << result.err;
}

// #21 item 5: a shape that is two boxes 4 mm apart, one clamped, under gravity, run with
// fem at default sizes. Mesh_3 used to bridge the gap with 264 cells, so the free box
// hung on the clamped one (1.7 mm instead of 54 mm after 10 steps); the exact mesh of
// box-built shapes keeps them apart and the free box falls freely.
TEST(GeometryPieces, TheFreeBoxOfTwoBoxesFourMillimetresApartFallsFreely) {
  const auto out = fresh_directory("two_boxes") / "run";
  const auto result = run_altfem(
      {"run", source_path("tests/cli/scenes/two_boxes.json").string(), "--method", "fem", "--out", out.string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::string check = "/usr/bin/python3 " + source_path("tests/cli/check_free_fall.py").string() + " " +
                            out.string() + " 0.3 0.104 0 1 0.204 0.1 -9.81 0.01 10";
  EXPECT_EQ(std::system(check.c_str()), 0) << "the free box did not fall freely (see output above)";
}

}  // namespace
}  // namespace altfem::test
