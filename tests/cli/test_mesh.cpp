// `altfem mesh`: builds and writes a method's mesh without solving; the VTU is read back
// with meshio and compared with the printed facts; fcm's kept cells; unknown sources are exit 2.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.hpp"

namespace altfem::test {
namespace {

/// Runs `altfem mesh SCENE --method METHOD [extra] --json`, checks the VTU against the
/// printed facts with meshio, and returns the facts.
nlohmann::json mesh_facts_checked_by_meshio(const std::string& scene, const std::string& method,
                                            const std::vector<std::string>& extra = {}) {
  const auto out = fresh_directory("mesh_" + method);
  std::vector<std::string> arguments{"mesh",  source_path(scene).string(), "--method", method, "--out", out.string(),
                                     "--json"};
  arguments.insert(arguments.end(), extra.begin(), extra.end());
  const CommandResult result = run_altfem(arguments);
  EXPECT_EQ(result.exit_code, 0) << result.err;
  if (result.exit_code != 0) return {};
  std::ofstream(out / "facts.json") << result.out;
  const std::string check = "/usr/bin/python3 " + source_path("tests/cli/check_mesh_output.py").string() + " " +
                            (out / "mesh.vtu").string() + " " + (out / "facts.json").string();
  EXPECT_EQ(std::system(check.c_str()), 0) << "meshio disagrees with the printed facts (see output above)";
  return nlohmann::json::parse(result.out);
}

void expect_mesh_matches_facts(const std::string& scene, const std::string& method, long long expected_cells) {
  const nlohmann::json facts = mesh_facts_checked_by_meshio(scene, method);
  ASSERT_FALSE(facts.is_null());
  EXPECT_EQ(facts["cells"]["total"].get<long long>(), expected_cells);
  // The cells fill the geometry: a straight-sided mesh of a box has its exact volume.
  EXPECT_LT(std::abs(facts["volume_relative_difference"].get<double>()), 1e-12);
  EXPECT_GT(facts["faces"]["boundary"].get<int>(), 0);
}

TEST(MeshCommand, DgMeshOfAGmshCubeIsPolyhedraReadByMeshio) {
  expect_mesh_matches_facts("scenes/cube_msh.json", "dg", 24);
}

TEST(MeshCommand, FemMeshOfTheCantileverIsWritten) { expect_mesh_matches_facts("scenes/cantilever.json", "fem", 80); }

TEST(MeshCommand, SlicedBunnyIsPolyhedraWithTheSurfaceVolume) {
  const nlohmann::json facts =
      mesh_facts_checked_by_meshio("scenes/bunny.json", "harmonic", {"--source", "slice", "--resolution", "8"});
  ASSERT_FALSE(facts.is_null());
  // Exact slicing of the surface: the cells hold its enclosed volume.
  EXPECT_LT(std::abs(facts["volume_relative_difference"].get<double>()), 1e-12);
  EXPECT_GT(facts["cells"]["hexahedra"].get<int>(), 0);
  EXPECT_GT(facts["cells"]["cut"].get<int>(), 0);
  EXPECT_EQ(facts["slicing"]["grid"], nlohmann::json::array({9, 9, 8}));
  // Slivers below 1e-3 of a cell were merged away.
  EXPECT_GE(facts["smallest_cell_volume"].get<double>(),
            1e-3 * std::pow(facts["slicing"]["cell_size"].get<double>(), 3) * (1 - 1e-12));
}

TEST(MeshCommand, OutEndingInVtuIsTheFileWritten) {
  const auto out = fresh_directory("mesh_file") / "sliced.vtu";
  const CommandResult result = run_altfem({"mesh", source_path("scenes/bunny.json").string(), "--method", "dg",
                                           "--source", "slice", "--resolution", "4", "--out", out.string(), "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(nlohmann::json::parse(result.out)["file"].get<std::string>(), out.string());
  EXPECT_TRUE(std::filesystem::is_regular_file(out));
}

TEST(MeshCommand, OctreeGradedCubeIsWrittenWithCoarseCells) {
  // The Gmsh cube sliced through its boundary surface, inside joined into octree cells.
  const nlohmann::json facts = mesh_facts_checked_by_meshio(
      "scenes/cube_msh.json", "dg", {"--source", "slice", "--resolution", "24", "--octree-levels", "2"});
  ASSERT_FALSE(facts.is_null());
  EXPECT_GT(facts["cells"]["coarse"].get<int>(), 0);
  EXPECT_EQ(facts["cells"]["coarse"], facts["slicing"]["octree_coarse_cells"]);
  EXPECT_LT(std::abs(facts["volume_relative_difference"].get<double>()), 1e-12);
  // A level-2 cell holds 64 grid cells.
  EXPECT_NEAR(facts["largest_cell_volume"].get<double>(), 64 * std::pow(facts["slicing"]["cell_size"].get<double>(), 3),
              1e-12);
}

// fcm's mesh is its kept background cells, as `run` builds them.
TEST(MeshCommand, FcmMeshIsTheKeptBackgroundCells) {
  const auto out = fresh_directory("mesh-fcm") / "sphere.vtu";
  const CommandResult result = run_altfem(
      {"mesh", source_path("scenes/sphere.json").string(), "--method", "fcm", "--out", out.string(), "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json facts = nlohmann::json::parse(result.out);
  EXPECT_GT(facts["cells"]["cut"].get<int>(), 0);
  EXPECT_EQ(facts["elements"]["hex20"].get<int>(),
            facts["cells"]["inside"].get<int>() + facts["cells"]["cut"].get<int>());
  EXPECT_LT(facts["cut_cell_points"]["final"].get<long long>(), facts["cut_cell_points"]["initial"].get<long long>());
  EXPECT_TRUE(std::filesystem::exists(out));
}

TEST(MeshCommand, UnbuiltSourcesAreBadInputWithOneLine) {
  for (const auto& arguments : std::vector<std::vector<std::string>>{
           {"mesh", source_path("scenes/cantilever.json").string(), "--method", "fcm", "--source", "slice"},
           {"mesh", source_path("scenes/cantilever.json").string(), "--method", "dg", "--source", "slicing"},
           {"mesh", source_path("scenes/cantilever.json").string(), "--method", "fem", "--source", "slice"},
           {"mesh", source_path("scenes/cantilever.json").string(), "--method", "dg", "--source", "slice",
            "--resolution", "0"}}) {
    const CommandResult result = run_altfem(arguments);
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_EQ(lines_of(result.err).size(), 1u) << result.err;
  }
}

}  // namespace
}  // namespace altfem::test
