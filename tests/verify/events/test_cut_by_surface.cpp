// A cut event whose blade is a triangulated surface file (docs/scene-schema.md, "Events";
// shared/mesh/cut_by_surface.hpp), with every method:
//   - two triangles in the plane x = 0.5 over the bar held at both ends cut it as that
//     plane does: two cantilevers, each exactly the half bar meshed alone;
//   - a V of four triangles, its fold on the grid plane x = 0.7, cuts a wedge out of the
//     swinging cantilever: the volume and mass are conserved (fcm: up to the α-weighted
//     fictitious parts of its new cut cells, exactly predicted), the surface opens, and the wedge, which
//     nothing holds, falls freely — each backward-Euler step adds exactly m g dt to its
//     momentum;
//   - a closed ball of 80 triangles cuts its volume out of a cube standing on the floor,
//     every method (fcm and fem: their tetrahedra split only near each triangle,
//     cut_tetrahedral_mesh_by_surface.cpp), and the ball, which nothing holds, falls freely.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "app/method_registry.hpp"
#include "shared/mesh/surface_mesh.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/scene/scene_override.hpp"
#include "shared/simulation/simulation.hpp"
#include "tests/verify/events/piece_momentum.hpp"
#include "tests/verify/events/static_answer.hpp"

namespace altfem {
namespace {

const std::filesystem::path scenes = std::filesystem::path(ALTFEM_SOURCE_DIR) / "tests/verify/events/scenes";

class CutBySurface : public ::testing::TestWithParam<std::string> {};

TEST_P(CutBySurface, TwoTrianglesAlongCellFacesMakeTheBarTwoCantilevers) {
  const StaticAnswer cut =
      solve_static(scenes / "bar_held_at_both_ends.json", GetParam(),
                   {parse_scene_override("events=[{\"time\": 0, \"cut\": {\"surface\": \"blade_at_midspan.obj\"}}]")});
  const StaticAnswer half = solve_static(scenes / "half_bar.json", GetParam());
  ASSERT_LT(half.vertical_mass, 0.0);
  EXPECT_NEAR(cut.vertical_mass, 2 * half.vertical_mass, 1e-10 * std::abs(half.vertical_mass));
  EXPECT_NEAR(cut.energy, 2 * half.energy, 1e-10 * half.energy);
}

// Within the V of v_blade.obj: above both arms, z − 0.04 > 2 |x − 0.7|.
bool in_wedge(const Eigen::Vector3d& x) { return x.z() - 0.04 > 2 * std::abs(x.x() - 0.7); }

TEST_P(CutBySurface, AVCutsAWedgeOutThatFallsFreely) {
  const Scene scene = load_scene(scenes / "cantilever_cut.json",
                                 {parse_scene_override("events=[{\"time\": 0.02, \"cut\": {\"surface\": "
                                                       "\"v_blade.obj\"}}]")});
  const SceneGeometry geometry = load_scene_geometry(scene);
  const MethodDescription& method = cli::find_method(GetParam());
  Simulation simulation(scene, geometry, GetParam(), method.factory, method.rebuild);
  for (int step = 0; step < 5; ++step) simulation.integrator().step(simulation.state());
  const EventRecord record = simulation.apply(scene.events.at(0));
  EXPECT_LE(std::abs(record.conserved["volume_change"].get<double>()), 1e-12);
  // fcm weighs each cut cell's whole rule by α = 1e-6 (Longva et al. 2020 §5.3): the two
  // cells of 0.001 m³ the V separates become four cut cells, adding 4 α × 0.001 m³ to the
  // bar's 0.01 m³ of mass; the others conserve the mass exactly.
  const double mass_jump = GetParam() == "fcm" ? 4 * 1e-6 * 0.001 / 0.01 : 0.0;
  EXPECT_NEAR(record.conserved["mass_change"].get<double>(), mass_jump, 1e-12 + 1e-5 * mass_jump);
  ASSERT_TRUE(record.facts.contains("surface"));
  EXPECT_EQ(record.facts["surface"]["pieces_left_whole"], 0);
  EXPECT_GT(record.facts["surface"]["cap_triangles"].get<int>(), 0);
  // The wedge: its triangle in (x, z), apex (0.7, 0.04), base 0.06 at z = 0.1, across 0.1 m.
  const double wedge_mass = 1000 * 0.5 * 0.06 * 0.06 * 0.1;
  EXPECT_NEAR(momentum_where(simulation, in_wedge, 1000).mass, wedge_mass,
              GetParam() == "fcm" ? 2e-6 * 1000 * 0.001 : 1e-10);
  expect_free_fall(simulation, in_wedge, 1000, scene.time.dt, 4);
}

class CutByClosedSurface : public ::testing::TestWithParam<std::string> {};

TEST_P(CutByClosedSurface, AClosedBallCutOutOfACubeFallsFreely) {
  const Scene scene = load_scene(scenes / "cube_on_floor.json");
  const SceneGeometry geometry = load_scene_geometry(scene);
  const MethodDescription& method = cli::find_method(GetParam());
  Simulation simulation(scene, geometry, GetParam(), method.factory, method.rebuild);
  const EventRecord record = simulation.apply(scene.events.at(0));
  EXPECT_LE(std::abs(record.conserved["volume_change"].get<double>()), 1e-12);
  // fcm's stabilisation weighs each piece of a cell the cut makes by α (1e-6) × the whole
  // cell: at most 2α of the cube's mass, a cell's two pieces.
  const double stabilised = GetParam() == "fcm" ? 2e-6 : 0;
  EXPECT_LE(std::abs(record.conserved["mass_change"].get<double>()), stabilised + 1e-12);
  EXPECT_EQ(record.facts["surface"]["cap_triangles"], 160);  // the ball's 80 triangles, once per side
  // The ball is convex: inside it is inside every triangle's plane.
  const SurfaceMesh ball = read_surface(scenes / "ball_blade.off");
  const auto in_ball = [&](const Eigen::Vector3d& x) {
    for (Eigen::Index t = 0; t < ball.triangles.rows(); ++t) {
      const Eigen::Vector3d a = ball.vertices.row(ball.triangles(t, 0)), b = ball.vertices.row(ball.triangles(t, 1)),
                            c = ball.vertices.row(ball.triangles(t, 2));
      if ((b - a).cross(c - a).dot(x - a) >= 0) return false;
    }
    return true;
  };
  const double ball_mass = 1000 * surface_volume(ball);
  EXPECT_NEAR(momentum_where(simulation, in_ball, 1000).mass, ball_mass, 1e-10 * ball_mass + stabilised * 1000);
  expect_free_fall(simulation, in_ball, 1000, scene.time.dt, 3);
}

// Cut while the cube moves (two steps settling on the floor): dg's transfer, each piece
// with its parent's polynomial (and a cell merged from pieces of several parents piece by
// piece, test_cut.cpp's CutMerge), keeps the momentum to round-off.
TEST(CutBySurfaceDg, AClosedBallCutOutOfAMovingCubeKeepsItsMomentum) {
  const Scene scene = load_scene(scenes / "cube_on_floor.json");
  const SceneGeometry geometry = load_scene_geometry(scene);
  const MethodDescription& method = cli::find_method("dg");
  Simulation simulation(scene, geometry, "dg", method.factory, method.rebuild);
  for (int step = 0; step < 2; ++step) simulation.integrator().step(simulation.state());
  const EventRecord record = simulation.apply(scene.events.at(0));
  EXPECT_LE(record.conserved["momentum_change"].get<double>(), 1e-12);
  EXPECT_LE(std::abs(record.conserved["mass_change"].get<double>()), 1e-12);
}

INSTANTIATE_TEST_SUITE_P(CuttingMethods, CutBySurface, ::testing::Values("dg", "harmonic", "fcm", "fem"),
                         [](const auto& info) { return info.param; });
INSTANTIATE_TEST_SUITE_P(CuttingMethods, CutByClosedSurface, ::testing::Values("dg", "harmonic", "fcm", "fem"),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace altfem
