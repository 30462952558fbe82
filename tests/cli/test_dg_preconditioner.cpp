// `altfem run --method dg` with an iterative linear solver and the key
// /discretization/dg/preconditioner (issue #18): every preconditioner runs, the two-level and
// multilevel ones take fewer PCG iterations than block Jacobi alone, and a bad name — or a mesh
// whose vertices outnumber the DG unknowns — exits 2 with one line naming the key.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.hpp"

namespace altfem::test {
namespace {

// summary.json's linear_iterations of a pcg run of the tiny beam with `preconditioner`.
long pcg_iterations(const std::filesystem::path& out, const std::string& preconditioner) {
  const auto result = run_altfem({"run", source_path("tests/cli/scenes/tiny_beam.json").string(), "--method", "dg",
                                  "--out", (out / preconditioner).string(), "--set", "solver/linear=pcg", "--set",
                                  "discretization/dg/preconditioner=" + preconditioner});
  EXPECT_EQ(result.exit_code, 0) << result.err;
  std::ifstream in(out / preconditioner / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(in);
  EXPECT_EQ(summary["options"]["discretization"]["dg"]["preconditioner"], preconditioner);
  return summary["linear_iterations"].get<long>();
}

TEST(DgPreconditioner, TwoLevelAndMultilevelTakeFewerPcgIterationsThanBlockJacobi) {
  const auto out = fresh_directory("dg_preconditioner");
  const long two_level = pcg_iterations(out, "two_level"), block_jacobi = pcg_iterations(out, "block_jacobi");
  const long multilevel = pcg_iterations(out, "multilevel");
  EXPECT_GT(two_level, 0);
  EXPECT_LT(two_level, block_jacobi);
  EXPECT_GT(multilevel, 0);
  EXPECT_LT(multilevel, block_jacobi);
}

TEST(DgPreconditioner, AnUnknownNameExitsTwoNamingTheKey) {
  const auto out = fresh_directory("dg_preconditioner_bad");
  const auto result = run_altfem({"run", source_path("tests/cli/scenes/tiny_beam.json").string(), "--method", "dg",
                                  "--out", (out / "run").string(), "--set", "discretization/dg/preconditioner=amg"});
  EXPECT_EQ(result.exit_code, 2);
  ASSERT_EQ(lines_of(result.err).size(), 1u) << result.err;
  EXPECT_NE(result.err.find("/discretization/dg/preconditioner"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("two_level"), std::string::npos) << result.err;
}

// The sphere sliced by a 2³ grid: 8 cut cells carrying every vertex of the surface mesh.
TEST(DgPreconditioner, AVertexSpaceLargerThanTheDgSpaceExitsTwoNamingTheKey) {
  const auto out = fresh_directory("dg_preconditioner_not_coarse");
  const auto result =
      run_altfem({"run", source_path("scenes/sphere.json").string(), "--method", "dg", "--out", (out / "run").string(),
                  "--set", "discretization/dg/mesh=slice", "--set", "discretization/dg/slice/resolution=2", "--set",
                  "solver/linear=pcg", "--set", "discretization/dg/preconditioner=two_level"});
  EXPECT_EQ(result.exit_code, 2);
  ASSERT_EQ(lines_of(result.err).size(), 1u) << result.err;
  EXPECT_NE(result.err.find("/discretization/dg/preconditioner"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("block_jacobi"), std::string::npos) << result.err;
  EXPECT_FALSE(std::filesystem::exists(out / "run" / "summary.json"));
}

}  // namespace
}  // namespace altfem::test
