// `altfem quadrature monomials|cell` end to end: the Fig. 4 rows as JSON, the VTU files
// of one cell's rules (read back with meshio), and bad arguments exiting 2.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.hpp"

namespace altfem::test {
namespace {

TEST(QuadratureCommand, MonomialsJsonRowsMeetTheFigure4Bounds) {
  const auto result = run_altfem({"quadrature", "monomials", "--cell", "hex20", "--order", "4", "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto rows = nlohmann::json::parse(result.out);
  ASSERT_EQ(rows.size(), 4u);
  for (const auto& row : rows) {
    EXPECT_LE(row["simplified"]["points"].get<int>(), row["basis_size"].get<int>());
    EXPECT_LE(row["simplified"]["max_relative_error"].get<double>(), 1e-11);
    EXPECT_GT(row["simplified"]["min_weight"].get<double>(), 0.0);
    EXPECT_TRUE(row["simplified"]["inside"].get<bool>());
  }
}

TEST(QuadratureCommand, BadArgumentsExitTwoWithOneLine) {
  for (const std::vector<std::string>& arguments :
       {std::vector<std::string>{"quadrature", "monomials", "--cell", "wedge6"},
        std::vector<std::string>{"quadrature", "monomials", "--cell", "hex8", "--order", "0"},
        std::vector<std::string>{"quadrature", "monomials", "--cell", "hex8", "--simplifier", "glpk"},
        std::vector<std::string>{"quadrature", "cell", "--scene", source_path("scenes/sphere.json").string(), "--cell",
                                 "4,0,0", "--resolution", "4"}}) {
    const auto result = run_altfem(arguments);
    EXPECT_EQ(result.exit_code, 2) << result.out << result.err;
    EXPECT_EQ(lines_of(result.err).size(), 1u) << result.err;
  }
}

TEST(QuadratureCommand, CellWritesRulesAsVtuPoints) {
  const auto folder = fresh_directory("quadrature_cell");
  const auto result = run_altfem({"quadrature", "cell", "--scene", source_path("scenes/sphere.json").string(), "--cell",
                                  "0,1,1", "--resolution", "3", "--order", "3", "--out", folder.string(), "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto report = nlohmann::json::parse(result.out);
  EXPECT_EQ(report["cut_cells"].get<int>(), 1);
  EXPECT_LE(report["final_points"].get<int>(), 20);
  EXPECT_GT(report["initial_points"].get<int>(), report["final_points"].get<int>());
  // The simplified rule's physical weights add up to the clipped volume (meshio reads it).
  const std::string script =
      "import meshio,sys; m=meshio.read(sys.argv[1]); w=m.point_data['physical_weight']; "
      "sys.exit(0 if abs(w.sum()-float(sys.argv[2]))<=1e-12*float(sys.argv[2]) and w.min()>0 else 1)";
  const std::string command = "/usr/bin/python3 -c \"" + script + "\" " + (folder / "simplified_rule.vtu").string() +
                              " " + report["clipped_volume"].dump();
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
}

}  // namespace
}  // namespace altfem::test

namespace altfem::test {
namespace {

TEST(QuadratureConditioning, PrintsTheFigure5Rows) {
  const CommandResult result = run_altfem({"quadrature", "conditioning", "--cell", "hex8", "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json rows = nlohmann::json::parse(result.out);
  ASSERT_EQ(rows.size(), 30u);  // 10 fractions × stabilisation 0, 1e-6, and the ghost penalty
  for (const auto& row : rows)
    for (const char* preconditioner : {"none", "jacobi", "schwarz"}) {
      EXPECT_GE(row["condition_number"][preconditioner].get<double>(), 1.0);
      EXPECT_GE(row["pcg_iterations"][preconditioner].get<int>(), 1);
    }
  EXPECT_DOUBLE_EQ(rows.back()["volume_fraction"].get<double>(), std::pow(2.0, -30));
  // The last ten rows: the ghost penalty (default γ) without stabilisation, which keeps
  // the unpreconditioned κ orders of magnitude below the plain run's at 2^-30.
  EXPECT_GT(rows.back()["ghost_penalty"].get<double>(), 0.0);
  EXPECT_EQ(rows.back()["stabilization"].get<double>(), 0.0);
  EXPECT_LT(1e6 * rows.back()["condition_number"]["none"].get<double>(),
            rows[9]["condition_number"]["none"].get<double>());
}

TEST(QuadratureConditioning, GhostPenaltyMustBePositive) {
  const CommandResult result = run_altfem({"quadrature", "conditioning", "--cell", "hex8", "--ghost-penalty", "-1"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("--ghost-penalty"), std::string::npos) << result.err;
}

TEST(QuadratureConditioning, UnknownCellIsBadInput) {
  const CommandResult result = run_altfem({"quadrature", "conditioning", "--cell", "tet20"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("--cell: expected tet4, tet10, hex8 or hex20, got 'tet20'"), std::string::npos)
      << result.err;
}

}  // namespace
}  // namespace altfem::test
