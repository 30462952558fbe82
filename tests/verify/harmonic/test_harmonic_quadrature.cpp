// The MFS cells' volume rules compared (issue 19, "Consistency under quadrature"; Martin
// et al. 2008 §6 integrate by bounding-box subdivision or Monte Carlo) on the 48-sided
// prism in pure bending that verify_manufactured's harmonic convergence study slices
// (tests/verify/manufactured/bending_prism_scene.hpp), here at 8 cells along its height,
// run as `altfem run --method harmonic --set discretization/harmonic/...` would. For each
// `rule` (and the cone rule's simplifiers): the points per MFS cell, the setup time (bases
// + tabulation, timings_s.quadrature), the L2 and H1 errors; and the patch test — the
// largest force a constant stress leaves on a node off the boundary, relative to the
// largest on any node — with and without harmonic_tabulation's consistency correction, on
// the same mesh with MFS bases on every cell (basis `mfs`), and with the method's default
// `auto` below the table (grid hexahedra keep their trilinear basis: their rectangular
// faces' bilinear traces are the face coordinates the MFS cells next to them use).
// Checked: the corrected patch test ≤ 1e-10 under every rule and with `auto`, and the uncorrected one far
// from it; the simplified cone rules at the default strength 2 (10 points for cells of up
// to 30 nodes, a rank-deficient stiffness) lose H1 accuracy, at strength 4 (35 points)
// hardly; the bounding-box rules spend many more points for errors within 2% of the cone
// rule's. This table is what docs/scene-schema.md's `rule` and `simplifier` defaults cite,
// printed by four tests (the cone rules; each bounding-box rule beside the cone rule), each
// under 30 s.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "app/method_registry.hpp"
#include "polyhedral/harmonic_element_bases.hpp"
#include "polyhedral/harmonic_scene_block.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/scene/scene_override.hpp"
#include "shared/simulation/run_simulation.hpp"
#include "tests/verify/manufactured/bending_prism_scene.hpp"

namespace altfem::harmonic {
namespace {

struct RuleCase {
  std::string name;
  std::vector<std::string> settings;  ///< --set assignments under discretization/harmonic/
  HarmonicQuadrature quadrature;      ///< the same, for the patch test's tabulation
  int strength = 2;                   ///< quadrature_order
};

// Names a case by its name in test output (instead of its bytes).
void PrintTo(const RuleCase& test, std::ostream* out) { *out << test.name; }

struct RuleRow {
  double points_per_cell, setup_seconds, l2, h1, uncorrected, corrected;
};

const std::filesystem::path& output_folder() {
  static const std::filesystem::path folder = std::filesystem::path(ALTFEM_BINARY_DIR) / "verify_harmonic_quadrature";
  return folder;
}

constexpr int resolution = 8;  // cells along the prism's height

Scene sliced_prism(const std::vector<std::string>& settings) {
  static const std::filesystem::path file = test::write_bending_scene(output_folder());
  std::vector<SceneOverride> overrides{
      parse_scene_override("discretization/harmonic/slice/resolution=" + std::to_string(resolution))};
  for (const std::string& setting : settings)
    overrides.push_back(parse_scene_override("discretization/harmonic/" + setting));
  Scene scene = load_scene(file, overrides);
  cli::resolve_method_blocks(scene, {"harmonic"});
  return scene;
}

// The largest force Σ_e Σ_q w_q σ ∇N_i(x_q) on a node off the mesh's boundary faces under a
// constant stress σ, relative to the largest on any node: zero for a consistent rule.
double interior_ghost_force(const PolyhedralMesh& mesh, const TabulatedElements& elements) {
  Eigen::Matrix3d stress;
  stress << 1.0, 0.3, -0.2, 0.3, 2.0, 0.1, -0.2, 0.1, 1.5;
  Eigen::MatrixXd forces = Eigen::MatrixXd::Zero(mesh.nodes.rows(), 3);
  for (int e = 0; e < elements.size(); ++e) {
    const ElementView element = elements[e];
    for (int q = 0; q < element.point_count(); ++q)
      forces(element.basis, Eigen::all) += element.weights[q] * element.gradients_at(q) * stress;  // σ symmetric
  }
  std::vector<bool> boundary(static_cast<size_t>(mesh.nodes.rows()), false);
  for (int face = 0; face < mesh.face_count(); ++face)
    if (mesh.is_boundary_face(face))
      for (int node : mesh.faces[face]) boundary[node] = true;
  double interior = 0;
  for (Eigen::Index node = 0; node < forces.rows(); ++node)
    if (!boundary[node]) interior = std::max(interior, forces.row(node).norm());
  return interior / forces.rowwise().norm().maxCoeff();
}

const RuleCase cone_rule{"cone, none", {"simplifier=none"}, {.simplifier = std::nullopt}};

// Runs each case on the sliced prism and its patch tests on the method's mesh with MFS
// bases on every cell; prints the rows. The corrected patch test holds under every rule,
// and the correction has work to do (the uncorrected one fails).
std::vector<RuleRow> compare_rules(const std::vector<RuleCase>& cases) {
  const Scene scene = sliced_prism({"basis=mfs"});
  const HarmonicSpec spec = harmonic_spec(scene);
  const PolyhedralMesh mesh = build_polyhedral_scene_mesh(spec.mesh, load_scene_geometry(scene)).sliced.mesh;
  const HarmonicElementBases bases(mesh, spec.basis, spec.mfs);

  const MethodDescription& method = cli::find_method("harmonic");
  std::printf("[ rules    ] bending prism sliced at %d cells along its height; patch test with basis mfs\n",
              resolution);
  std::printf("[ rules    ] %-22s %11s %9s %10s %10s %14s %12s\n", "rule, strength", "points/cell", "setup (s)",
              "L2 error", "H1 error", "patch uncorr.", "patch corr.");
  std::vector<RuleRow> rows;
  for (const RuleCase& test : cases) {
    const Scene run_scene = sliced_prism(test.settings);
    const nlohmann::json summary =
        run_simulation(run_scene, load_scene_geometry(run_scene), "harmonic", method.factory, output_folder() / "run");
    EXPECT_EQ(summary["status"], "ok") << test.name;
    HarmonicQuadrature quadrature = test.quadrature;
    quadrature.consistent = false;
    const double uncorrected = interior_ghost_force(mesh, bases.tabulate(test.strength, quadrature));
    quadrature.consistent = true;
    const double corrected = interior_ghost_force(mesh, bases.tabulate(test.strength, quadrature));
    const RuleRow row{
        summary["facts"]["mfs_quadrature_points"].get<double>() / summary["elements"]["mfs_polyhedron"].get<double>(),
        summary["timings_s"]["quadrature"].get<double>(),
        summary["field_errors"]["l2"].get<double>(),
        summary["field_errors"]["h1_seminorm"].get<double>(),
        uncorrected,
        corrected};
    std::printf("[ rules    ] %-22s %11.1f %9.2f %10.4e %10.4e %14.2e %12.2e\n", test.name.c_str(), row.points_per_cell,
                row.setup_seconds, row.l2, row.h1, row.uncorrected, row.corrected);
    EXPECT_LT(row.corrected, 1e-10) << test.name;
    EXPECT_GT(row.uncorrected, 1e-6) << test.name;  // the correction has work to do
    rows.push_back(row);
  }
  return rows;
}

// The cone rule and its simplifications; the patch test with `auto` (the method's default:
// trilinear hexahedra beside MFS cells).
TEST(HarmonicQuadrature, ConeRulesComparedOnASlicedPrism) {
  const std::vector<RuleCase> cases{
      cone_rule,
      {"cone, caratheodory", {"simplifier=caratheodory"}, {.simplifier = SimplificationMethod::caratheodory}},
      {"cone, nnls", {"simplifier=nnls"}, {.simplifier = SimplificationMethod::nonnegative_least_squares}},
      {"cone, lp", {"simplifier=lp"}, {.simplifier = SimplificationMethod::linear_program}},
      {"cone, caratheodory, 4",
       {"simplifier=caratheodory", "quadrature_order=4"},
       {.simplifier = SimplificationMethod::caratheodory},
       4}};
  const std::vector<RuleRow> rows = compare_rules(cases);
  ASSERT_EQ(rows.size(), cases.size());
  const RuleRow& cone = rows[0];
  for (size_t k = 1; k <= 3; ++k) {  // simplified at strength 2: at most C(5, 3) points, too few
    EXPECT_LE(rows[k].points_per_cell, 10) << cases[k].name;
    EXPECT_NEAR(rows[k].l2, cone.l2, 0.1 * cone.l2) << cases[k].name;
    EXPECT_GT(rows[k].h1, 1.3 * cone.h1) << cases[k].name;  // measured 1.6–2.3×: the default `none`
    EXPECT_LT(rows[k].h1, 3 * cone.h1) << cases[k].name;
  }
  // Simplified at strength 4: C(7, 3) = 35 points, within 10% of the full rule at strength 2.
  EXPECT_LE(rows[4].points_per_cell, 35);
  EXPECT_NEAR(rows[4].h1, cone.h1, 0.1 * cone.h1);

  const Scene plain_scene = sliced_prism({});
  const HarmonicSpec spec = harmonic_spec(plain_scene);
  const PolyhedralMesh mesh = build_polyhedral_scene_mesh(spec.mesh, load_scene_geometry(plain_scene)).sliced.mesh;
  const HarmonicElementBases plain_bases(mesh, spec.basis, spec.mfs);
  const double auto_patch = interior_ghost_force(mesh, plain_bases.tabulate(2, {}));
  std::printf("[ rules    ] patch test with basis auto, cone rule, corrected: %.2e\n", auto_patch);
  EXPECT_LT(auto_patch, 1e-10);
}

// The bounding-box rules of Martin et al. §6 against the cone rule: many more points, no
// gain. One test per rule, each beside its own cone run (the three together took 33 s).
class BoundingBoxRule : public testing::TestWithParam<RuleCase> {};

TEST_P(BoundingBoxRule, SpendsManyMorePointsForTheConeRulesErrors) {
  const std::vector<RuleRow> rows = compare_rules({cone_rule, GetParam()});
  ASSERT_EQ(rows.size(), 2u);
  const RuleRow &cone = rows[0], &box = rows[1];
  EXPECT_GT(box.points_per_cell, 2.5 * cone.points_per_cell);
  EXPECT_NEAR(box.l2, cone.l2, 0.02 * cone.l2);
  EXPECT_NEAR(box.h1, cone.h1, 0.02 * cone.h1);
}

std::string rule_name(const testing::TestParamInfo<RuleCase>& info) {
  std::string name;
  for (const char c : info.param.name)
    if (std::isalnum(static_cast<unsigned char>(c))) name += c;
  return name;
}

INSTANTIATE_TEST_SUITE_P(HarmonicQuadrature, BoundingBoxRule,
                         testing::Values(RuleCase{"subdivision, 2 levels",
                                                  {"rule=subdivision", "subdivision_levels=2"},
                                                  {.kind = HarmonicRuleKind::subdivision, .subdivision_levels = 2}},
                                         RuleCase{"subdivision, 3 levels",
                                                  {"rule=subdivision", "subdivision_levels=3"},
                                                  {.kind = HarmonicRuleKind::subdivision, .subdivision_levels = 3}},
                                         RuleCase{"monte_carlo, 1000",
                                                  {"rule=monte_carlo", "monte_carlo_points=1000"},
                                                  {.kind = HarmonicRuleKind::monte_carlo, .monte_carlo_points = 1000}}),
                         rule_name);

}  // namespace
}  // namespace altfem::harmonic
