// `altfem mesh`: builds and writes a method's mesh without solving; the VTU is read back
// with meshio and compared with the printed facts; fcm and unknown sources are exit 2.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.hpp"

namespace altfem::test {
namespace {

void expect_mesh_matches_facts(const std::string& scene, const std::string& method, long long expected_cells) {
  const auto out = fresh_directory("mesh_" + method);
  const CommandResult result =
      run_altfem({"mesh", source_path(scene).string(), "--method", method, "--out", out.string(), "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json facts = nlohmann::json::parse(result.out);
  EXPECT_EQ(facts["cells"]["total"].get<long long>(), expected_cells);
  // The cells fill the geometry: a straight-sided mesh of a box has its exact volume.
  EXPECT_LT(std::abs(facts["volume_relative_difference"].get<double>()), 1e-12);
  EXPECT_GT(facts["faces"]["boundary"].get<int>(), 0);
  std::ofstream(out / "facts.json") << result.out;
  const std::string check = "/usr/bin/python3 " + source_path("tests/cli/check_mesh_output.py").string() + " " +
                            (out / "mesh.vtu").string() + " " + (out / "facts.json").string();
  EXPECT_EQ(std::system(check.c_str()), 0) << "meshio disagrees with the printed facts (see output above)";
}

TEST(MeshCommand, DgMeshOfAGmshCubeIsPolyhedraReadByMeshio) {
  expect_mesh_matches_facts("scenes/cube_msh.json", "dg", 24);
}

TEST(MeshCommand, FemMeshOfTheCantileverIsWritten) { expect_mesh_matches_facts("scenes/cantilever.json", "fem", 80); }

TEST(MeshCommand, FcmAndUnbuiltSourcesAreBadInputWithOneLine) {
  for (const auto& arguments : std::vector<std::vector<std::string>>{
           {"mesh", source_path("scenes/cantilever.json").string(), "--method", "fcm"},
           {"mesh", source_path("scenes/cantilever.json").string(), "--method", "dg", "--source", "slicing"}}) {
    const CommandResult result = run_altfem(arguments);
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_EQ(lines_of(result.err).size(), 1u) << result.err;
  }
}

}  // namespace
}  // namespace altfem::test
