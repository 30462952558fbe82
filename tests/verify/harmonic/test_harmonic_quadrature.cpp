// The MFS cells' volume rules compared (issue 19, "Consistency under quadrature"; Martin
// et al. 2008 §6 integrate by bounding-box subdivision or Monte Carlo): on the ball of
// radius ½ sliced at 4 cells per side with the manufactured solution of
// tests/verify/manufactured/scenes/sliced_ball.json, for each /discretization/harmonic/rule
// (and the cone rule's simplifiers), run as `altfem run --method harmonic --set ...` would:
// the points per MFS cell, the setup time (bases + tabulation, timings_s.quadrature), the
// L2 and H1 errors; and on the same mesh and bases the patch test — the largest force a
// constant stress leaves on an interior node, relative to the largest on any node — with
// and without harmonic_tabulation's consistency correction. Checked: the corrected patch
// test ≤ 1e-10 under every rule; the simplified cone rules give the full cone rule's
// errors; the bounding-box rules, with more points, give larger errors. The table is what
// docs/scene-schema.md's `rule` and `simplifier` defaults cite.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "app/method_registry.hpp"
#include "polyhedral/harmonic_element_bases.hpp"
#include "polyhedral/harmonic_scene_block.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/scene/scene_override.hpp"
#include "shared/simulation/run_simulation.hpp"

namespace altfem::harmonic {
namespace {

struct RuleCase {
  std::string name;
  std::vector<std::string> settings;  ///< --set assignments under discretization/harmonic/
  HarmonicQuadrature quadrature;      ///< the same, for the patch test's tabulation
};

struct RuleRow {
  double points_per_cell, setup_seconds, l2, h1, uncorrected, corrected;
};

const std::filesystem::path ball_scene =
    std::filesystem::path(ALTFEM_SOURCE_DIR) / "tests" / "verify" / "manufactured" / "scenes" / "sliced_ball.json";

Scene sliced_ball(const std::vector<std::string>& settings) {
  std::vector<SceneOverride> overrides{parse_scene_override("discretization/harmonic/mesh=slice"),
                                       parse_scene_override("discretization/harmonic/slice/resolution=4")};
  for (const std::string& setting : settings)
    overrides.push_back(parse_scene_override("discretization/harmonic/" + setting));
  Scene scene = load_scene(ball_scene, overrides);
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

TEST(HarmonicQuadrature, RulesComparedOnASlicedBall) {
  const std::vector<RuleCase> cases{
      {"cone, none", {"simplifier=none"}, {.simplifier = std::nullopt}},
      {"cone, caratheodory", {"simplifier=caratheodory"}, {.simplifier = SimplificationMethod::caratheodory}},
      {"cone, nnls", {"simplifier=nnls"}, {.simplifier = SimplificationMethod::nonnegative_least_squares}},
      {"cone, lp", {"simplifier=lp"}, {.simplifier = SimplificationMethod::linear_program}},
      {"subdivision, 2 levels", {"rule=subdivision", "subdivision_levels=2"},
       {.kind = HarmonicRuleKind::subdivision, .subdivision_levels = 2}},
      {"subdivision, 3 levels", {"rule=subdivision", "subdivision_levels=3"},
       {.kind = HarmonicRuleKind::subdivision, .subdivision_levels = 3}},
      {"monte_carlo, 1000", {"rule=monte_carlo", "monte_carlo_points=1000"},
       {.kind = HarmonicRuleKind::monte_carlo, .monte_carlo_points = 1000}},
      {"monte_carlo, 8000", {"rule=monte_carlo", "monte_carlo_points=8000"},
       {.kind = HarmonicRuleKind::monte_carlo, .monte_carlo_points = 8000}}};

  // The patch test's mesh and bases: the method's own, once.
  const Scene scene = sliced_ball({});
  const HarmonicSpec spec = harmonic_spec(scene);
  const PolyhedralMesh mesh = build_polyhedral_scene_mesh(spec.mesh, load_scene_geometry(scene)).sliced.mesh;
  const HarmonicElementBases bases(mesh, spec.basis, spec.mfs);

  const MethodDescription& method = cli::find_method("harmonic");
  const std::filesystem::path folder = std::filesystem::path(ALTFEM_BINARY_DIR) / "verify_harmonic_quadrature";
  std::printf("[ rules    ] ball sliced at 4 cells per side, quadrature_order %d\n", spec.quadrature_order);
  std::printf("[ rules    ] %-22s %10s %9s %10s %10s %15s %13s\n", "rule", "points/cell", "setup (s)", "L2 error",
              "H1 error", "patch uncorr.", "patch corr.");
  std::vector<RuleRow> rows;
  for (const RuleCase& test : cases) {
    const Scene run_scene = sliced_ball(test.settings);
    const nlohmann::json summary =
        run_simulation(run_scene, load_scene_geometry(run_scene), "harmonic", method.factory, folder / "run");
    ASSERT_EQ(summary["status"], "ok") << test.name;
    HarmonicQuadrature quadrature = test.quadrature;
    quadrature.consistent = false;
    const double uncorrected = interior_ghost_force(mesh, bases.tabulate(spec.quadrature_order, quadrature));
    quadrature.consistent = true;
    const double corrected = interior_ghost_force(mesh, bases.tabulate(spec.quadrature_order, quadrature));
    const RuleRow row{summary["facts"]["mfs_quadrature_points"].get<double>() /
                          summary["elements"]["mfs_polyhedron"].get<double>(),
                      summary["timings_s"]["quadrature"].get<double>(), summary["field_errors"]["l2"].get<double>(),
                      summary["field_errors"]["h1_seminorm"].get<double>(), uncorrected, corrected};
    std::printf("[ rules    ] %-22s %10.1f %9.2f %10.4e %10.4e %15.2e %13.2e\n", test.name.c_str(), row.points_per_cell,
                row.setup_seconds, row.l2, row.h1, row.uncorrected, row.corrected);
    rows.push_back(row);
  }
  for (size_t k = 0; k < rows.size(); ++k) EXPECT_LT(rows[k].corrected, 1e-10) << cases[k].name;
  const RuleRow& cone = rows[0];
  for (size_t k = 1; k <= 3; ++k) {  // the simplified cone rules: exact to the same strength
    EXPECT_NEAR(rows[k].l2, cone.l2, 1e-3 * cone.l2) << cases[k].name;
    EXPECT_NEAR(rows[k].h1, cone.h1, 1e-3 * cone.h1) << cases[k].name;
    EXPECT_LT(rows[k].points_per_cell, cone.points_per_cell) << cases[k].name;
  }
  for (size_t k = 4; k < rows.size(); ++k) {  // the bounding-box rules: more points, larger errors
    EXPECT_GT(rows[k].l2, cone.l2) << cases[k].name;
    EXPECT_GT(rows[k].points_per_cell, rows[1].points_per_cell) << cases[k].name;
    EXPECT_GT(rows[k].uncorrected, 1e-8) << cases[k].name;  // the correction has work to do
  }
}

}  // namespace
}  // namespace altfem::harmonic
