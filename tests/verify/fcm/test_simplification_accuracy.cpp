// Longva et al. 2020 §6.3: simplifying the cut cells' quadrature (§4.4) costs almost no
// accuracy. The twisting hollow cylinder (scenes/twisting_cylinder.json, its first 5
// steps) with Hex20 FCM on a 3 × 3 × 12 grid, once with the default simplification and
// once with the full intersection rules, against a Tet10 fem reference: the two surface
// errors agree within 5%. Prints the point reduction and the assembly-time ratio.
#include <gtest/gtest.h>

#include <cstdio>

#include "fcm/fcm_method.hpp"
#include "shared/compare/surface_error.hpp"
#include "shared/fem/fem_method.hpp"
#include "shared/scene/scene_override.hpp"
#include "shared/simulation/run_simulation.hpp"

namespace altfem::fcm {
namespace {

struct SimulatedRun {
  nlohmann::json summary;
  SurfaceFrame surface;
};

SimulatedRun simulate(const std::string& method, const MethodFactory& factory, std::vector<std::string> assignments) {
  assignments.insert(assignments.end(), {"/time/steps=5", "/output={\"every\": 5, \"volume\": false}"});
  std::vector<SceneOverride> overrides;
  for (const auto& assignment : assignments) overrides.push_back(parse_scene_override(assignment));
  const Scene scene = load_scene(ALTFEM_SOURCE_DIR "/scenes/twisting_cylinder.json", overrides);
  const SceneGeometry geometry = load_scene_geometry(scene);
  const auto folder = std::filesystem::temp_directory_path() / ("altfem_simplification_" + method +
                                                                std::to_string(assignments.size()));
  std::filesystem::remove_all(folder);
  const nlohmann::json summary = run_simulation(scene, geometry, method, factory, folder);
  SimulatedRun result{summary, read_surface_frame(folder / summary["surface"].get<std::string>())};
  std::filesystem::remove_all(folder);
  return result;
}

TEST(SimplifiedQuadrature, TwistingCylinderSurfaceErrorWithinFivePercentOfTheFullRules) {
  const SimulatedRun reference = simulate("fem", make_fem_method, {"/discretization/fem/max_cell_size=0.1"});
  const std::vector<std::string> grid{"/discretization/fcm/resolution=[3,3,12]"};
  const SimulatedRun simplified = simulate("fcm", make_fcm_method, grid);
  std::vector<std::string> full = grid;
  full.push_back("/discretization/fcm/simplifier=\"none\"");
  const SimulatedRun unsimplified = simulate("fcm", make_fcm_method, full);

  const SurfaceError simplified_error = surface_error(simplified.surface, reference.surface);
  const SurfaceError full_error = surface_error(unsimplified.surface, reference.surface);
  const auto points = [](const SimulatedRun& run) { return run.summary["facts"]["cut_cell_points"]["final"].get<double>(); };
  const auto assembly = [](const SimulatedRun& run) { return run.summary["timings_s"]["assembly"].get<double>(); };
  std::printf("  %-22s %14s %12s %12s\n", "cut-cell rules", "cut-cell points", "assembly (s)", "RMS error");
  std::printf("  %-22s %14.0f %12.3f %12.4e\n", "full (intersection)", points(unsimplified), assembly(unsimplified),
              full_error.rms);
  std::printf("  %-22s %14.0f %12.3f %12.4e\n", "simplified (default)", points(simplified), assembly(simplified),
              simplified_error.rms);
  std::printf("  point reduction %.1fx, assembly-time ratio simplified/full %.3f\n",
              points(unsimplified) / points(simplified), assembly(simplified) / assembly(unsimplified));

  EXPECT_GT(points(unsimplified), 10 * points(simplified));
  EXPECT_NEAR(simplified_error.rms, full_error.rms, 0.05 * full_error.rms);
}

}  // namespace
}  // namespace altfem::fcm
