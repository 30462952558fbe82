// scenes/bar_cut.json (issue #33), every method: the 1 × 0.1 × 0.1 m bar clamped at x = 0
// swings down under its weight and is cut through at x = 0.55 at t = 0.2 s. The free half
// falls freely: nothing holds it and its internal forces sum to zero, so each
// backward-Euler step adds exactly m g dt to its vertical momentum. The clamped half,
// relieved of the free half's weight, rings about its new rest at its first bending
// frequency, f = 1.875² / (2π L²) √(EI / ρA) = 16.9 Hz for L = 0.55 m (Euler–Bernoulli):
// over the 60 steps of 0.005 s after the cut, 5.1 periods, its vertical momentum changes
// sign about 10 times (backward Euler damps the ringing and a little lengthens its period).
// Were it still holding the free half, it would fall with it.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "app/method_registry.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/simulation/simulation.hpp"
#include "tests/verify/events/piece_momentum.hpp"

namespace altfem {
namespace {

class BarCut : public ::testing::TestWithParam<std::string> {};

TEST_P(BarCut, TheFreeHalfFallsAndTheClampedHalfRings) {
  const Scene scene = load_scene(std::filesystem::path(ALTFEM_SOURCE_DIR) / "scenes/bar_cut.json");
  const SceneGeometry geometry = load_scene_geometry(scene);
  const MethodDescription& method = cli::find_method(GetParam());
  Simulation simulation(scene, geometry, GetParam(), method.factory, method.rebuild);
  const double dt = scene.time.dt, density = 1000, g = -9.81;
  const auto steps_before = static_cast<int>(std::lround(scene.events.at(0).time / dt));
  for (int step = 0; step < steps_before; ++step) simulation.integrator().step(simulation.state());
  const EventRecord record = simulation.apply(scene.events.at(0));
  EXPECT_EQ(record.facts["surface"]["pieces_left_whole"], 0);
  const auto free_half = [](const Eigen::Vector3d& x) { return x.x() > 0.55; };
  const auto clamped_half = [](const Eigen::Vector3d& x) { return x.x() < 0.55; };
  PieceMomentum falling = momentum_where(simulation, free_half, density);
  EXPECT_NEAR(falling.mass, 4.5, 1e-3 * 4.5);  // fcm: and α ρ of its cut cell's fictitious part
  int sign_changes = 0;
  double last = momentum_where(simulation, clamped_half, density).momentum_z;
  for (int step = 0; step < 60; ++step) {
    simulation.integrator().step(simulation.state());
    const PieceMomentum fallen = momentum_where(simulation, free_half, density);
    EXPECT_NEAR(fallen.momentum_z - falling.momentum_z, falling.mass * g * dt, 1e-6 * falling.mass * std::abs(g) * dt)
        << "step " << step;
    falling = fallen;
    const double ringing = momentum_where(simulation, clamped_half, density).momentum_z;
    sign_changes += (ringing > 0) != (last > 0);
    last = ringing;
  }
  EXPECT_GE(sign_changes, 8);
  EXPECT_LE(sign_changes, 12);
}

INSTANTIATE_TEST_SUITE_P(CuttingMethods, BarCut, ::testing::Values("dg", "harmonic", "fcm", "fem"),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace altfem
