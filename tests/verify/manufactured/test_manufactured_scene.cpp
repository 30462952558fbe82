// Convergence to the manufactured solution of scenes/manufactured.json (unit cube,
// linear material, λ = 15, μ = 10; u = a (sin πx sin πy sin πz, eˣ sin πy, x² sin πz),
// body force f = −div σ(u) and the boundary field u written out as expressions), and of
// scenes/manufactured_half_ball.json (a curved domain: the half-ball clamped on its flat
// face, the traction σ(u)·n on the sphere written with the surface normal; Longva et al.
// 2020, §6.6, Fig. 10: FCM at the optimal rates h² and h³ on cut cells). The
// scene runs through run_simulation with `--set`-style overrides of its resolution and
// element, and summary.json's field_errors (L2 and H1 seminorm of the final state) must
// fall at the element's rates between the two finest meshes: p + 1 and p within ±0.25
// (dg's L2 rate may exceed p + 1 by more: below) for degree-p elements (Ciarlet, The
// Finite Element Method for Elliptic Problems,
// Thm. 3.2.2 and §3.2 for L2 by the Aubin–Nitsche argument). A deal.II-style table of
// every run is printed.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "app/method_registry.hpp"
#include "shared/scene/scene_override.hpp"
#include "shared/simulation/run_simulation.hpp"

namespace altfem {
namespace {

struct Case {
  std::string method;
  std::string element_key, element;  ///< a key of the block and its value (the element, basis or degree)
  std::vector<int> resolutions;
  double l2_rate, h1_rate;
  std::string scene = "manufactured";
  std::array<int, 3> divisor{1, 1, 1};  ///< the grid is n / divisor cells along each axis
  /// How far the L2 rate may exceed l2_rate (it may fall short by 0.25): above 0.25 for a
  /// method that converges faster than its degree on these meshes.
  double l2_rate_excess = 0.25;
};

// gtest prints a parameter in test names and failures: the case, not its bytes.
void PrintTo(const Case& test, std::ostream* stream) {
  *stream << test.scene << " " << test.method << " " << test.element;
}

struct Row {
  int resolution;
  long long dofs;
  double l2, h1;
};

std::vector<Row> run_case(const Case& test) {
  const std::filesystem::path scene_file = std::filesystem::path(ALTFEM_SOURCE_DIR) / "scenes" / (test.scene + ".json");
  const MethodDescription& method = cli::find_method(test.method);
  std::vector<Row> rows;
  for (int n : test.resolutions) {
    const std::string prefix = "discretization/" + test.method + "/";
    // harmonic's mesh is the fem block under `convert`.
    const std::string resolution_key = test.method == "harmonic" ? "convert/resolution" : "resolution";
    const std::string resolution = "[" + std::to_string(n / test.divisor[0]) + "," +
                                   std::to_string(n / test.divisor[1]) + "," + std::to_string(n / test.divisor[2]) +
                                   "]";
    const std::vector<SceneOverride> overrides{parse_scene_override(prefix + resolution_key + "=" + resolution),
                                               parse_scene_override(prefix + test.element_key + "=" + test.element),
                                               parse_scene_override("output/volume=false"),
                                               parse_scene_override("output/surface=false")};
    Scene scene = load_scene(scene_file, overrides);
    cli::resolve_method_blocks(scene, {test.method});
    const SceneGeometry geometry = load_scene_geometry(scene);
    const std::filesystem::path output =
        std::filesystem::path(ALTFEM_BINARY_DIR) / "verify_manufactured" /
        (test.scene + "_" + test.method + "_" + test.element + "_" + std::to_string(n));
    const nlohmann::json summary = run_simulation(scene, geometry, test.method, method.factory, output);
    EXPECT_EQ(summary["status"], "ok");
    const nlohmann::json& errors = summary.at("field_errors");
    rows.push_back(
        {n, summary["dofs"].get<long long>(), errors["l2"].get<double>(), errors["h1_seminorm"].get<double>()});
  }
  return rows;
}

double rate(const Row& coarse, const Row& fine, double Row::*error) {
  return std::log(coarse.*error / fine.*error) / std::log(static_cast<double>(fine.resolution) / coarse.resolution);
}

void print_table(const Case& test, const std::vector<Row>& rows) {
  std::printf("%s: %s %s\n  cells/axis   dofs   L2 error   rate   H1 error   rate\n", test.scene.c_str(),
              test.method.c_str(), test.element.c_str());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    std::printf("  %10d %6lld  %.3e", rows[i].resolution, rows[i].dofs, rows[i].l2);
    if (i > 0) std::printf("  %5.2f", rate(rows[i - 1], rows[i], &Row::l2));
    else std::printf("       ");
    std::printf("  %.3e", rows[i].h1);
    if (i > 0) std::printf("  %5.2f", rate(rows[i - 1], rows[i], &Row::h1));
    std::printf("\n");
  }
}

class ManufacturedScene : public ::testing::TestWithParam<Case> {};

TEST_P(ManufacturedScene, FieldErrorsFallAtTheElementRates) {
  const Case& test = GetParam();
  const std::vector<Row> rows = run_case(test);
  print_table(test, rows);
  ASSERT_GE(rows.size(), 2u);
  const Row& coarse = rows[rows.size() - 2];
  const Row& fine = rows.back();
  EXPECT_GE(rate(coarse, fine, &Row::l2), test.l2_rate - 0.25);
  EXPECT_LE(rate(coarse, fine, &Row::l2), test.l2_rate + test.l2_rate_excess);
  EXPECT_NEAR(rate(coarse, fine, &Row::h1), test.h1_rate, 0.25);
}

std::string case_name(const ::testing::TestParamInfo<Case>& info) {
  return (info.param.scene == "manufactured" ? "" : info.param.scene + "_") + info.param.method + "_" +
         info.param.element;
}

INSTANTIATE_TEST_SUITE_P(Fem, ManufacturedScene,
                         ::testing::Values(Case{"fem", "element", "tet4", {2, 4, 8}, 2, 1},
                                           Case{"fem", "element", "tet10", {2, 4, 8}, 3, 2},
                                           Case{"fem", "element", "hex8", {2, 4, 8}, 2, 1},
                                           Case{"fem", "element", "hex20", {2, 4, 8}, 3, 2}),
                         case_name);

// The other methods where their rates are clean on these meshes: fcm on the cube is its
// uncut background grid; harmonic with MFS bases on every cell (its closed-form Hex8 cells
// would repeat fem); dg k = 2 with its default penalty (k = 1 on hexahedra is still far
// from its asymptotic rate at 8 cells per axis: docs/verification.md, "Manufactured solutions"). dg's L2
// error converges faster than h³ on these uniform grids with MFEM's κ = 9 (3.37 at 4 → 8,
// 3.48 at 6 → 12, 3.49 at 8 → 12; H1 2.06), so its L2 rate may exceed 3 by 0.5.
INSTANTIATE_TEST_SUITE_P(OtherMethods, ManufacturedScene,
                         ::testing::Values(Case{"fcm", "cell", "hex20", {4, 8}, 3, 2},
                                           Case{"harmonic", "basis", "mfs", {2, 4}, 2, 1},
                                           Case{"dg", "degree", "2", {4, 8}, 3, 2, "manufactured", {1, 1, 1}, 0.5}),
                         case_name);

// Fig. 10 with an exact answer: the flat face lies on a grid plane (n × n × n/2 cells
// over [−1, 1]² × [0, 1]); every other boundary cell is cut. The clamped half-ball of
// tests/verify/fcm/test_convergence.cpp, against a Tet10 reference, is singular at the
// rim; this one is not, so the rates are the element's (measured: Hex8 L2 1.86, 1.98;
// Hex20 3.07, 2.99).
INSTANTIATE_TEST_SUITE_P(
    CurvedDomain, ManufacturedScene,
    ::testing::Values(Case{"fcm", "cell", "hex8", {4, 8, 16}, 2, 1, "manufactured_half_ball", {1, 1, 2}},
                      Case{"fcm", "cell", "hex20", {4, 8, 16}, 3, 2, "manufactured_half_ball", {1, 1, 2}}),
    case_name);

}  // namespace
}  // namespace altfem
