// Convergence of the polyhedral methods on hexahedrally sliced meshes of curved shapes
// (mesh "slice": Kaufmann et al. 2009, §9.2; Martin et al. 2008, §7), run from scene
// files through run_simulation as `altfem run --set discretization/<method>/slice/resolution=n`
// would; the rates come from summary.json's field_errors between the two finest meshes.
//
// dg (issue 18, Kaufmann et al. 2009 Figs. 1 and 2 in 3D): the ball of radius 1/2 in the
// unit cube with the manufactured solution of scenes/manufactured.json (its body force and
// u* imposed weakly on every boundary face, §4.2), interior penalty: polynomials of degree
// k = 1, 2 reproduced exactly, and L2 and H1 rates k + 1 and k (± 0.3) for k = 1, 2, 3.
//
// harmonic (issue 19): the prism in pure bending of bending_prism_scene.hpp; u* is
// quadratic, so the trilinear and MFS bases converge at L2 ≥ 1.8 and H1 ≥ 0.9.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "app/method_registry.hpp"
#include "polyhedral/mfs_options.hpp"
#include "shared/scene/scene_override.hpp"
#include "shared/simulation/run_simulation.hpp"
#include "tests/verify/manufactured/bending_prism_scene.hpp"

namespace altfem {
namespace {

struct Row {
  int resolution;
  long long dofs, cells;
  double l2, h1;
  double smallest_fraction = 0;  ///< dg: the smallest cell's volume over a grid cell's
  double eta = 0;                ///< dg: η used (Pa), after `doublings`
  int doublings = 0;
};

const std::filesystem::path& output_folder() {
  static const std::filesystem::path folder = std::filesystem::path(ALTFEM_BINARY_DIR) / "verify_sliced_convergence";
  return folder;
}

struct Case {
  std::string name, method;
  std::vector<std::string> settings;  ///< --set assignments under discretization/<method>/
  std::vector<int> resolutions;       ///< slice/resolution: cells along the longest side
};

/// `scene_settings`: --set assignments of the scene itself (its solution and loads).
std::vector<Row> run_case(const Case& test, const std::filesystem::path& scene_file,
                          const std::vector<std::string>& scene_settings = {}) {
  const MethodDescription& method = cli::find_method(test.method);
  std::vector<Row> rows;
  for (int n : test.resolutions) {
    const std::string prefix = "discretization/" + test.method + "/";
    std::vector<SceneOverride> overrides{parse_scene_override(prefix + "slice/resolution=" + std::to_string(n))};
    for (const std::string& setting : test.settings) overrides.push_back(parse_scene_override(prefix + setting));
    for (const std::string& setting : scene_settings) overrides.push_back(parse_scene_override(setting));
    Scene scene = load_scene(scene_file, overrides);
    cli::resolve_method_blocks(scene, {test.method});
    const SceneGeometry geometry = load_scene_geometry(scene);
    const nlohmann::json summary = run_simulation(scene, geometry, test.method, method.factory,
                                                  output_folder() / (test.name + "_" + std::to_string(n)));
    EXPECT_EQ(summary["status"], "ok");
    EXPECT_EQ(summary["facts"]["source"], "slice");
    const nlohmann::json& errors = summary.at("field_errors");
    long long cells = 0;
    for (const auto& [kind, count] : summary["elements"].items()) cells += count.get<long long>();
    Row row{n, summary["dofs"].get<long long>(), cells, errors["l2"].get<double>(),
            errors["h1_seminorm"].get<double>()};
    const nlohmann::json& facts = summary["facts"];
    if (facts.contains("penalty")) {
      row.smallest_fraction =
          facts["smallest_cell_volume"].get<double>() / std::pow(facts["slicing"]["cell_size"].get<double>(), 3);
      row.eta = facts["penalty"]["eta_pa"].get<double>();
      row.doublings = facts["penalty"]["doublings"].get<int>();
    }
    rows.push_back(row);
  }
  return rows;
}

double rate(const Row& coarse, const Row& fine, double Row::*error) {
  return std::log(coarse.*error / fine.*error) / std::log(static_cast<double>(fine.resolution) / coarse.resolution);
}

// deal.II's convergence table: errors and their rates against the grid's cells per side
// (for dg also the smallest cell's volume fraction of a grid cell, η and its doublings).
void print_table(const std::string& name, const std::vector<Row>& rows) {
  std::printf("%s (sliced)\n  cells/side  cells    dofs  min vol.  eta (Pa)  L2 error   rate   H1 error   rate\n",
              name.c_str());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    std::printf("  %10d %6lld %7lld  %.2e  %5.0f/%d  %.3e", rows[i].resolution, rows[i].cells, rows[i].dofs,
                rows[i].smallest_fraction, rows[i].eta, rows[i].doublings, rows[i].l2);
    if (i > 0) std::printf("  %5.2f", rate(rows[i - 1], rows[i], &Row::l2));
    else std::printf("       ");
    std::printf("  %.3e", rows[i].h1);
    if (i > 0) std::printf("  %5.2f", rate(rows[i - 1], rows[i], &Row::h1));
    std::printf("\n");
  }
}

// Runs the case, prints its table and checks the rates between its two meshes.
void expect_rates(const Case& test, const std::filesystem::path& scene_file, double l2_rate, double h1_rate) {
  const std::vector<Row> rows = run_case(test, scene_file);
  print_table(test.name, rows);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_GE(rate(rows[0], rows[1], &Row::l2), l2_rate);
  EXPECT_GE(rate(rows[0], rows[1], &Row::h1), h1_rate);
}

const std::filesystem::path ball_scene =
    std::filesystem::path(ALTFEM_SOURCE_DIR) / "tests" / "verify" / "manufactured" / "scenes" / "sliced_ball.json";

// Consistency on cut cells (Kaufmann et al. 2009, Fig. 1, on sliced meshes): interior
// penalty reproduces a solution in its polynomial space, whatever the cells' shapes —
// affine for k = 1, quadratic (with its constant body force) for k = 2.
TEST(SlicedConvergence, DgReproducesPolynomialsOfItsDegreeOnABall) {
  const std::vector<std::vector<std::string>> problems{
      {"degree=1", R"json(exact_displacement=["a*(x + 2*y - z)", "a*(3*x - y + z)", "a*(x + y + 2*z)"])json",
       R"json(boundary_conditions/0/motion/displacement=["a*(x + 2*y - z)", "a*(3*x - y + z)", "a*(x + y + 2*z)"])json",
       R"json(loads/body_force=["0", "0", "0"])json"},
      {"degree=2", R"json(exact_displacement=["a*x^2", "0", "0"])json",
       R"json(boundary_conditions/0/motion/displacement=["a*x^2", "0", "0"])json",
       R"json(loads/body_force=["-2*a*(lambda + 2*mu)", "0", "0"])json"}};
  for (const auto& problem : problems) {
    std::vector<std::string> settings{problem[0]};
    std::vector<std::string> scene_settings(problem.begin() + 1, problem.end());
    const Case test{"dg_exact_" + problem[0].substr(problem[0].size() - 1), "dg", settings, {4}};
    const std::vector<Row> rows = run_case(test, ball_scene, scene_settings);
    ASSERT_EQ(rows.size(), 1u);
    std::printf("%s: sliced ball at 4 cells per side, L2 error %.2e, H1 error %.2e\n", test.name.c_str(), rows[0].l2,
                rows[0].h1);
    EXPECT_LT(rows[0].l2, 1e-12);
    EXPECT_LT(rows[0].h1, 1e-11);
  }
}

// Kaufmann et al. 2009 Fig. 2 on a sliced curved domain (issue 18: L2 rates within 0.3 of
// k + 1) with the penalty a user gets: MFEM's κ = (k+1)² (η = κ(λ+2μ)/2, c_f = 2) on the
// cell length ℓ(K) = 6 vol(K)/area(∂K) (docs/scene-schema.md, dg). Checked: that penalty
// is definite on every mesh (no doubling, so η is the same across the study) and the L2
// and H1 rates between the two meshes are k + 1 and k within 0.3.
// What the defaults replaced, measured on the same meshes: Kaufmann's eq. (20) scales each
// face's penalty by its own area, so the cut cells' small facets of the sphere are
// under-penalised, K needs 1–3 doublings that differ from mesh to mesh (k = 1: η 560 Pa at
// 6 cells, 140 at 12), and the rate is an artefact of the change (1.57); at a fixed η the
// rate is 0.5–1.0. η = 20 E (Kaufmann's default, 520 Pa here) is several times the
// smallest definite penalty and holds complete degree-1 and -2 polynomials so nearly
// continuous that they converge far below their rates at these sizes (k = 1 L2 0.85 at
// 12 → 16, k = 2 2.56 at 4 → 8). slice/sliver_fraction (0.001 to 0.2) changes none of the
// errors by more than 1% once the penalty follows ℓ(K).
/// `settings`: further --set assignments under discretization/dg/.
void expect_dg_rates(int degree, const std::vector<int>& resolutions, std::vector<std::string> settings = {}) {
  settings.push_back("degree=" + std::to_string(degree));
  const std::vector<Row> rows = run_case({"dg_k" + std::to_string(degree), "dg", settings, resolutions}, ball_scene);
  print_table("dg k = " + std::to_string(degree), rows);
  ASSERT_EQ(rows.size(), 2u);
  for (const Row& row : rows) EXPECT_EQ(row.doublings, 0) << row.resolution << " cells per side";
  EXPECT_NEAR(rate(rows[0], rows[1], &Row::l2), degree + 1, 0.3);
  EXPECT_NEAR(rate(rows[0], rows[1], &Row::h1), degree, 0.3);
}

// Degree 1 is the slowest to reach its rate: its error grows with the penalty on tangential
// jumps (complete linear polynomials held nearly continuous lock). With the whole
// κ(λ+2μ) on every jump component the default κ = 4 gave L2 rates 1.54, 1.67, 1.76 at
// 12 → 16 → 24 → 32 cells per side and only κ = 3 reached 1.74 at 16 → 24; with its λ part
// on normal jumps only (the default `lame_split`, Hansbo & Larson 2002) κ = 4 gives 1.75 at
// 16 → 24 (L2 6.2e-5 at 16), while κ = 3 is no longer definite on these meshes (one
// doubling, η 105 Pa, rate 1.66). ctest takes 16 → 20 (L2 1.73, H1 1.05; 12 → 16 is still
// at 1.66) in half the time; the docs' 16 → 24 is SlicedConvergenceFullSize.
TEST(SlicedConvergence, DgInteriorPenaltyDegreeOneOnABall) { expect_dg_rates(1, {16, 20}); }

TEST(SlicedConvergenceFullSize, DgInteriorPenaltyDegreeOneOnABall) { expect_dg_rates(1, {16, 24}); }

// L2 2.73, 3.21, 3.24 at 4 → 6 → 8 → 12.
TEST(SlicedConvergence, DgInteriorPenaltyDegreeTwoOnABall) { expect_dg_rates(2, {8, 12}); }

// L2 3.25, 3.97 at 3 → 4 → 6.
TEST(SlicedConvergence, DgInteriorPenaltyDegreeThreeOnABall) { expect_dg_rates(3, {4, 6}); }

TEST(SlicedConvergence, HarmonicOnABendingPrism) {
  // The default samples per edge: a cut cell of the 48-gon has up to ~40 edges, but the
  // samples' spacing comes from the cell's area, not its edge count (both meshes at 5
  // samples: 3.8 s CPU; 40 s for the 6-cell mesh alone when every edge got 5 centres).
  expect_rates({"harmonic", "harmonic", {}, {6, 12}}, test::write_bending_scene(output_folder()), 1.8, 0.9);
}

// What the MFS sampling (Martin et al. 2008 §5: 3–5 samples per edge) does to the solution
// a user gets: the bending prism at 12 cells per side, with the method's default bases
// (trilinear on the grid's hexahedra, MFS on the cut cells) and with MFS on every cell,
// against samples per edge. The default (mfs_options.hpp) must give the L2 and H1 errors
// of 6 samples within 2%: the basis time it saves (bench_polyhedral_element) costs the
// solution nothing measurable. ctest runs the default and 6; SlicedConvergenceFullSize adds
// 3 and 5, the table the default was picked from, printed with the C0 mismatch and
// nodal-interpolation tables of verify_harmonic_continuity and verify_harmonic
// (docs/performance.md, "The default of 4 samples per edge").
void expect_default_samples_within_two_percent_of_six(const std::set<int>& samples_per_edge) {
  const std::filesystem::path scene = test::write_bending_scene(output_folder());
  const int default_samples = harmonic::MfsOptions{}.edge_samples;
  std::printf(
      "harmonic, bending prism at 12 cells per side, against MFS samples per edge\n"
      "  basis  samples/edge   L2 error   H1 error   L2 / L2(6)   H1 / H1(6)\n");
  for (const std::string basis : {"auto", "mfs"}) {
    std::map<int, Row> rows;
    for (int samples : samples_per_edge)
      rows[samples] = run_case({"harmonic_" + basis + "_" + std::to_string(samples),
                                "harmonic",
                                {"basis=" + basis, "samples_per_edge=" + std::to_string(samples)},
                                {12}},
                               scene)
                          .front();
    for (const auto& [samples, row] : rows)
      std::printf("  %5s  %12d  %.3e  %.3e  %11.4f  %11.4f\n", basis.c_str(), samples, row.l2, row.h1,
                  row.l2 / rows.at(6).l2, row.h1 / rows.at(6).h1);
    EXPECT_NEAR(rows.at(default_samples).l2 / rows.at(6).l2, 1, 0.02) << basis;
    EXPECT_NEAR(rows.at(default_samples).h1 / rows.at(6).h1, 1, 0.02) << basis;
  }
}

TEST(SlicedConvergence, HarmonicErrorAgainstSamplesPerEdge) {
  expect_default_samples_within_two_percent_of_six({harmonic::MfsOptions{}.edge_samples, 6});
}

TEST(SlicedConvergenceFullSize, HarmonicErrorAgainstSamplesPerEdge) {
  expect_default_samples_within_two_percent_of_six({3, 4, 5, 6});
}

}  // namespace
}  // namespace altfem
