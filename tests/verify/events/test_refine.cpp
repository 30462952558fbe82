// A refine event (docs/scene-schema.md, "Events"; Kaufmann et al. 2009 §9.3, Martin et al.
// 2008 §8) with dg and harmonic, on the 1 × 0.1 × 0.1 m cantilever of 10 cells:
//   - An affine field is unchanged by any refinement, 1→8 or 1→2: carried across, it is the
//     refined method's own interpolation of the field, and its strain energy is still the
//     exact constant density × volume (the patch test's consistency on the refined mesh,
//     hanging nodes included).
//   - dg carries a quadratic field (its degree, zero on the clamp) across exactly: each
//     child keeps its parent's polynomial, a global polynomial has no jumps for the
//     penalty to weigh, so the total energy does not jump, to round-off, and neither do
//     the mass and momentum.
//   - The error indicator (the traction's jump across faces, its residual against the loads
//     on the boundary) marks where the stress is discontinuous or misses the load, whatever
//     its size (dg, harmonic and fem on its Hex8 grid).
//   - Marking follows the keys (dg, harmonic and fem): a region splits only the cells whose centroid it holds, a
//     cell split max_level times is not split again (nothing is rebuilt), and a cell whose
//     stress is below the threshold stays.
//   - A static scene with `cycles` k is solved at its load steps, then k times more, each
//     after a refinement, with a frame and a log line per solve.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "app/method_registry.hpp"
#include "shared/common/error.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/scene/scene_override.hpp"
#include "shared/simulation/run_simulation.hpp"
#include "shared/simulation/simulation.hpp"
#include "tests/verify/events/element_count.hpp"
#include "tests/verify/events/refine_checks.hpp"

namespace altfem {
namespace {

// A field zero on the clamp x = 0, so that dg's weak condition there adds nothing.
Eigen::Vector3d affine(const Eigen::Vector3d& x) { return Eigen::Vector3d(1e-3, 3e-4, -2e-4) * x.x(); }

struct RefineCase {
  std::string method, split;
  int cells_after;  // the clamp's half of the bar split: 5 + 5 × 8 or 5 + 5 × 2
};

void PrintTo(const RefineCase& test, std::ostream* out) { *out << test.method << " " << test.split; }

class Refine : public ::testing::TestWithParam<RefineCase> {};

TEST_P(Refine, AnAffineFieldIsUnchangedAndKeepsItsExactStrainEnergy) {
  const RefineCase& test = GetParam();
  const Scene scene = load_scene(cantilever_refine_scene,
                                 {clamp_half, parse_scene_override("events/0/refine/split=\"" + test.split + "\"")});
  const SceneGeometry geometry = load_scene_geometry(scene);
  const MethodDescription& method = cli::find_method(test.method);
  Simulation simulation(scene, geometry, test.method, method.factory, method.rebuild);
  simulation.state().displacement = simulation.method().interpolate(affine);
  const EventRecord record = simulation.apply(scene.events.at(0));
  EXPECT_EQ(record.facts["marked_cells"], 5);  // a uniform stress above the threshold 0
  EXPECT_EQ(element_count(simulation.method()), test.cells_after);
  EXPECT_LE(std::abs(record.conserved["volume_change"].get<double>()), 1e-12);

  const Eigen::VectorXd expected = simulation.method().interpolate(affine);
  const Eigen::VectorXd& carried = simulation.state().displacement;
  ASSERT_EQ(carried.size(), expected.size());
  EXPECT_LE((carried - expected).lpNorm<Eigen::Infinity>(), 1e-12 * expected.lpNorm<Eigen::Infinity>());

  Eigen::Matrix3d gradient = Eigen::Matrix3d::Zero();
  gradient.col(0) << 1e-3, 3e-4, -2e-4;
  const Eigen::Matrix3d strain = 0.5 * (gradient + gradient.transpose());
  const double E = 1e8, nu = 0.3, lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const double energy = (0.5 * lambda * strain.trace() * strain.trace() + mu * strain.squaredNorm()) * 0.01;
  // harmonic: the unsplit neighbour of the split cells holds hanging nodes, so it takes an
  // MFS basis, which reproduces affine fields to the MFS fit.
  const double tolerance = test.method == "harmonic" ? 1e-6 : 1e-10;
  EXPECT_NEAR(simulation.method().discretization().energy(expected), energy, tolerance * energy);
}

INSTANTIATE_TEST_SUITE_P(RefiningMethods, Refine,
                         ::testing::Values(RefineCase{"dg", "1to8", 45}, RefineCase{"dg", "1to2", 15},
                                           RefineCase{"harmonic", "1to8", 45}, RefineCase{"harmonic", "1to2", 15}),
                         [](const auto& info) { return info.param.method + "_" + info.param.split.substr(2); });

TEST(RefineDg, AQuadraticFieldCrossesWithoutAnEnergyJump) {
  const Scene scene = load_scene(cantilever_refine_scene, {clamp_half});
  const SceneGeometry geometry = load_scene_geometry(scene);
  const MethodDescription& method = cli::find_method("dg");
  Simulation simulation(scene, geometry, "dg", method.factory, method.rebuild);
  const auto quadratic = [](const Eigen::Vector3d& x) -> Eigen::Vector3d {
    return x.x() * Eigen::Vector3d(2e-3 * x.x() - 1e-3 * x.y(), 5e-4 + 3e-3 * x.z(), -4e-3 * x.x());
  };
  simulation.state().displacement = simulation.method().interpolate(quadratic);
  simulation.state().velocity = simulation.method().interpolate([](const Eigen::Vector3d& x) -> Eigen::Vector3d {
    return Eigen::Vector3d(0.1 * x.y() * x.z(), -0.2 * x.x() * x.x(), 0.3 * x.x() * x.y());
  });
  const EventRecord record = simulation.apply(scene.events.at(0));
  EXPECT_EQ(record.facts["marked_cells"], 5);
  EXPECT_EQ(element_count(simulation.method()), 5 + 5 * 8);
  EXPECT_GT(record.facts["hanging_nodes"].get<int>(), 0);
  EXPECT_LE(std::abs(record.conserved["energy_jump_relative"].get<double>()), 1e-12);
  // Each child holds its parent's polynomial, re-expanded in its own monomials.
  const Eigen::VectorXd expected = simulation.method().interpolate(quadratic);
  EXPECT_LE((simulation.state().displacement - expected).lpNorm<Eigen::Infinity>(),
            1e-12 * expected.lpNorm<Eigen::Infinity>());
  EXPECT_LE(std::abs(record.conserved["mass_change"].get<double>()), 1e-12);
  EXPECT_LE(std::abs(record.conserved["momentum_change"].get<double>()), 1e-12);
}

TEST(RefineMarking, ACellAtMaxLevelOrBelowTheThresholdIsNotSplit) {
  for (const std::string name : {"dg", "harmonic", "fem"}) {
    SCOPED_TRACE(name);
    const Scene scene = load_scene(cantilever_refine_scene);
    const SceneGeometry geometry = load_scene_geometry(scene);
    const MethodDescription& method = cli::find_method(name);
    Simulation simulation(scene, geometry, name, method.factory, method.rebuild);
    // Shear growing along the bar, u_z = 1e-3 x²: |σ| largest at the tip.
    const auto shear = [](const Eigen::Vector3d& x) -> Eigen::Vector3d { return {0, 0, 1e-3 * x.x() * x.x()}; };
    simulation.state().displacement = simulation.method().interpolate(shear);
    SceneEvent refine = scene.events.at(0);
    const double tip_stress = simulation.apply(refine).facts["largest_stress"].get<double>();
    const int cells = element_count(simulation.method());
    EXPECT_EQ(cells, 80);
    const EventRecord again = simulation.apply(refine);  // max_level 1: each child is at it
    EXPECT_EQ(again.facts["marked_cells"], 0);
    EXPECT_EQ(again.facts["at_max_level"], 80);
    EXPECT_EQ(again.dofs_after, again.dofs_before);
    // σ_xz = 2μ · 1e-3 x at the centroid (the mean over a cell is its centroid's value, for
    // harmonic's trilinear interpolant too — of the field interpolated on the children, not
    // the coarse one carried over): 0.6 × the last cell's (x = 0.95) marks the children with
    // centroids x > 0.57, 9 × 4.
    simulation.state().displacement = simulation.method().interpolate(shear);
    refine.refine.max_level = 2;
    refine.refine.threshold = 0.6 * tip_stress;
    EXPECT_EQ(simulation.apply(refine).facts["marked_cells"], 36);
  }
}

// The error indicator marks where the stress jumps, not where it is high: the bar in shear
// growing along it (u_z = 1e-3 x², σ_xz = μ ∂u_z/∂x) has cells whose mean stresses differ by
// μ · 2e-3 · 0.1 from one cell to the next, jumps of that size in the traction across every
// face normal to x and none across the others (the bar is one cell thick). Its boundary is
// loaded by the field's own traction σn = μ 2e-3 x (n_z, 0, n_x), which each side face
// meets, at its centroid, with its cell's mean: no residual there; the clamped end's is the
// reaction, left out. Each cell's indicator is the RMS residual over the faces it has
// (areas 0.01 m² each): an inner cell's two jumps among six faces, √(2/6) of a jump; the
// clamped cell's one among five, √(1/5); the free end's one jump and its end face's half
// jump (the traction at x = 1 against the cell's mean at 0.95) among six, √(1.25/6).
// Thresholds between those mark 10, 9, 8 and 0 cells, though the stress itself grows
// twentyfold along the bar: had the clamp's reaction counted, the clamped cell would weigh
// as the free end's.
TEST(RefineIndicator, TheTractionResidualMarksWhereTheStressIsDiscontinuousOrMissesTheLoad) {
  const SceneOverride field_traction = parse_scene_override(
      "loads/traction=[{\"region\": {\"box\": {\"min\": [-1, -1, -1], \"max\": [2, 2, 2]}}, "
      "\"traction\": [\"1e8 / 2.6 * 2e-3 * x * nz\", \"0\", \"1e8 / 2.6 * 2e-3 * x * nx\"]}]");
  for (const std::string name : {"dg", "harmonic", "fem"}) {
    SCOPED_TRACE(name);
    const Scene scene = load_scene(cantilever_refine_scene, {field_traction});
    const SceneGeometry geometry = load_scene_geometry(scene);
    const MethodDescription& method = cli::find_method(name);
    const double mu = 1e8 / (2 * 1.3), jump = mu * 2e-3 * 0.1;
    // √(1/5) = 0.4472, √(1.25/6) = 0.4564, √(1/3) = 0.5774
    for (const auto& [fraction, marked] : {std::pair{0.44, 10}, {0.452, 9}, {0.46, 8}, {0.58, 0}}) {
      Simulation simulation(scene, geometry, name, method.factory, method.rebuild);
      simulation.state().displacement =
          simulation.method().interpolate([](const Eigen::Vector3d& x) -> Eigen::Vector3d {
            return {0, 0, 1e-3 * x.x() * x.x()};
          });
      SceneEvent refine = scene.events.at(0);
      refine.refine.criterion = RefineCriterion::error_indicator;
      refine.refine.threshold = fraction * jump;
      const EventRecord record = simulation.apply(refine);
      EXPECT_NEAR(record.facts["largest_indicator"].get<double>(), jump / std::sqrt(3.0), 1e-9 * jump);
      EXPECT_EQ(record.facts["marked_cells"], marked) << fraction;
    }
  }
}

TEST(RefineCycles, AStaticSceneIsSolvedOncePerCycleAfterItsLastLoadStep) {
  const Scene scene =
      load_scene(cantilever_refine_scene,
                 {parse_scene_override("time={\"static\": true, \"load_steps\": 2}"),
                  parse_scene_override("events=[{\"time\": 0, \"refine\": {\"threshold\": 0, \"cycles\": 2}}]"),
                  parse_scene_override("discretization/dg/degree=1")});
  ASSERT_EQ(scene.events.size(), 2u);
  const std::filesystem::path output = std::filesystem::path(ALTFEM_BINARY_DIR) / "verify_refine_cycles";
  std::filesystem::remove_all(output);
  const nlohmann::json summary =
      run_simulation(scene, load_scene_geometry(scene), "dg", cli::find_method("dg"), output, 0.0);
  ASSERT_EQ(summary["status"], "ok");
  // Every cell carries the gravity's stress above 0: 10 → 80 → 640 cells of 4 monomials.
  const nlohmann::json& events = summary["events"];
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[0]["dofs"]["after"], 80 * 12);
  EXPECT_EQ(events[1]["dofs"]["after"], 640 * 12);
  for (int frame = 0; frame <= 4; ++frame)  // at rest, 2 load steps, 2 cycles
    EXPECT_TRUE(std::filesystem::exists(output / ("surface_00000" + std::to_string(frame) + ".vtu"))) << frame;
  EXPECT_FALSE(std::filesystem::exists(output / "surface_000005.vtu"));
}

}  // namespace
}  // namespace altfem
