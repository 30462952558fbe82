// Longva et al. 2020 §6.3: simplifying the cut cells' quadrature (§4.4) costs almost no
// accuracy (the paper's RMS distance 0.0149 m simplified, 0.0153 m with the full rules). The
// twisting hollow cylinder (scenes/twisting_cylinder.json) with Hex20 FCM on a 3 × 3 × 12
// grid, once with the default simplification and once with the full intersection rules,
// against a Tet10 fem reference (h = 0.1 m): the two surface errors agree within 5%, and
// simplification keeps under a tenth of the points. Prints the point reduction, the
// assembly-time ratio and the RMS distance between the two runs' surfaces (on the first
// step 7% of the error, mostly along it: the errors differ by 0.05%). ctest runs
// the first step on embedded tetrahedra of 0.12 m (694k full-rule points; errors 3.650e-6
// and 3.648e-6 of the diagonal, where a finer reference, h = 0.07, gives 4.064e-6 and
// 4.058e-6: the reference's own error is 1.5e-6). The scene's 0.06 m over its first 5 steps
// (2.8 million full-rule points, minutes of assembly) is SimplifiedQuadratureFullSize
// (docs/verification.md).
#include <gtest/gtest.h>

#include <cstdio>

#include "fcm/fcm_method.hpp"
#include "shared/compare/surface_error.hpp"
#include "shared/fem/method/fem_method.hpp"
#include "shared/scene/scene_override.hpp"
#include "shared/simulation/run_simulation.hpp"

namespace altfem::fcm {
namespace {

struct SimulatedRun {
  nlohmann::json summary;
  SurfaceFrame surface;
};

SimulatedRun simulate(const std::string& method, const MethodFactory& factory, std::vector<std::string> assignments,
                      int steps) {
  assignments.insert(assignments.end(), {"/time/steps=" + std::to_string(steps),
                                         "/output={\"every\": " + std::to_string(steps) + ", \"volume\": false}"});
  std::vector<SceneOverride> overrides;
  for (const auto& assignment : assignments) overrides.push_back(parse_scene_override(assignment));
  const Scene scene = load_scene(ALTFEM_SOURCE_DIR "/scenes/twisting_cylinder.json", overrides);
  const SceneGeometry geometry = load_scene_geometry(scene);
  // Under the build folder: two checkouts running this test at once must not share it.
  const auto folder = std::filesystem::path(ALTFEM_BINARY_DIR) / "verify_simplification" /
                      (method + std::to_string(assignments.size()));
  std::filesystem::remove_all(folder);
  const nlohmann::json summary = run_simulation(scene, geometry, method, factory, folder);
  SimulatedRun result{summary, read_surface_frame(folder / summary["surface"].get<std::string>())};
  std::filesystem::remove_all(folder);
  return result;
}

// `fcm_settings`: further assignments under /discretization/fcm/.
void expect_simplified_rules_as_accurate(int steps, const std::vector<std::string>& fcm_settings) {
  const SimulatedRun reference = simulate("fem", make_fem_method, {"/discretization/fem/max_cell_size=0.1"}, steps);
  std::vector<std::string> grid{"/discretization/fcm/resolution=[3,3,12]"};
  for (const std::string& setting : fcm_settings) grid.push_back("/discretization/fcm/" + setting);
  const SimulatedRun simplified = simulate("fcm", make_fcm_method, grid, steps);
  std::vector<std::string> full = grid;
  full.push_back("/discretization/fcm/simplifier=\"none\"");
  const SimulatedRun unsimplified = simulate("fcm", make_fcm_method, full, steps);

  const SurfaceError simplified_error = surface_error(simplified.surface, reference.surface);
  const SurfaceError full_error = surface_error(unsimplified.surface, reference.surface);
  const SurfaceError rules_difference = surface_error(simplified.surface, unsimplified.surface);
  const auto points = [](const SimulatedRun& run) {
    return run.summary["facts"]["cut_cell_points"]["final"].get<double>();
  };
  const auto assembly = [](const SimulatedRun& run) { return run.summary["timings_s"]["assembly"].get<double>(); };
  std::printf("  %-22s %14s %12s %12s\n", "cut-cell rules", "cut-cell points", "assembly (s)", "RMS error");
  std::printf("  %-22s %14.0f %12.3f %12.4e\n", "full (intersection)", points(unsimplified), assembly(unsimplified),
              full_error.rms);
  std::printf("  %-22s %14.0f %12.3f %12.4e\n", "simplified (default)", points(simplified), assembly(simplified),
              simplified_error.rms);
  std::printf("  point reduction %.1fx, assembly-time ratio simplified/full %.3f, RMS distance between the two %.4e\n",
              points(unsimplified) / points(simplified), assembly(simplified) / assembly(unsimplified),
              rules_difference.rms);

  EXPECT_GT(points(unsimplified), 10 * points(simplified));
  EXPECT_NEAR(simplified_error.rms, full_error.rms, 0.05 * full_error.rms);
}

TEST(SimplifiedQuadrature, TwistingCylinderSurfaceErrorWithinFivePercentOfTheFullRules) {
  expect_simplified_rules_as_accurate(1, {"embedded_cell_size=0.12"});
}

TEST(SimplifiedQuadratureFullSize, TwistingCylinderSurfaceErrorWithinFivePercentOfTheFullRules) {
  expect_simplified_rules_as_accurate(5, {});
}

}  // namespace
}  // namespace altfem::fcm
