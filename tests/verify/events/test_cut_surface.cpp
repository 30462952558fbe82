// The surface every method deforms, cut with the body (issue #33; docs/scene-schema.md,
// "Events"): a swinging cantilever (1 × 0.1 × 0.1 m, clamped at x = 0) is cut through at
// x = 0.55, and with every method
//   - the surface keeps its vertices at their indices and falls into two closed pieces
//     whose volumes are exactly the two parts of the box (caps included);
//   - the piece cut off falls (½ g t² = 17.7 mm in the 0.06 s after the cut, from its
//     swing) while the clamped part does not, and every point of the cut moves with its
//     own side: each copy as the surface next to it on its side, not as the other side.
// And a geometry without a common surface: dg and harmonic cut their own (OwnSurfaceCut).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>

#include "app/method_registry.hpp"
#include "shared/mesh/mesh_components.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/simulation/simulation.hpp"

namespace altfem {
namespace {

const std::filesystem::path scenes = std::filesystem::path(ALTFEM_SOURCE_DIR) / "tests/verify/events/scenes";

// Enclosed volume of the triangles of `surface` whose first vertex lies in `piece`.
double piece_volume(const SurfaceMesh& surface, const std::vector<int>& piece_of, int piece) {
  double volume = 0;
  for (Eigen::Index t = 0; t < surface.triangles.rows(); ++t) {
    if (piece_of[surface.triangles(t, 0)] != piece) continue;
    const Eigen::Vector3d a = surface.vertices.row(surface.triangles(t, 0)),
                          b = surface.vertices.row(surface.triangles(t, 1)),
                          c = surface.vertices.row(surface.triangles(t, 2));
    volume += a.dot(b.cross(c)) / 6;
  }
  return volume;
}

class CutSurface : public ::testing::TestWithParam<std::string> {};

TEST_P(CutSurface, OpensIntoTwoClosedPiecesAndEachSideMovesWithItsOwnMaterial) {
  const Scene scene = load_scene(scenes / "cantilever_cut.json");
  const SceneGeometry geometry = load_scene_geometry(scene);
  const MethodDescription& method = cli::find_method(GetParam());
  Simulation simulation(scene, geometry, GetParam(), method.factory, method.rebuild);
  const SurfaceMesh before = simulation.method().embedded_surface();
  for (int step = 0; step < 5; ++step) simulation.integrator().step(simulation.state());
  const EventRecord record = simulation.apply(scene.events.at(0));
  EXPECT_GT(record.facts["surface"]["cap_triangles"].get<int>(), 0);

  const SurfaceMesh& after = simulation.method().embedded_surface();
  const Eigen::Index kept = before.vertices.rows();
  ASSERT_GT(after.vertices.rows(), kept);
  EXPECT_EQ(after.vertices.topRows(kept), before.vertices);
  const std::vector<int> piece_of = surface_vertex_pieces(after);
  Eigen::Index nearest_clamp = 0, farthest = 0;
  before.vertices.col(0).minCoeff(&nearest_clamp);
  before.vertices.col(0).maxCoeff(&farthest);
  const int clamped = piece_of[nearest_clamp], free = piece_of[farthest];
  ASSERT_NE(clamped, free);
  for (std::size_t v = 0; v < piece_of.size(); ++v) ASSERT_TRUE(piece_of[v] == clamped || piece_of[v] == free);
  EXPECT_NEAR(piece_volume(after, piece_of, clamped), 0.55 * 0.01, 1e-15);
  EXPECT_NEAR(piece_volume(after, piece_of, free), 0.45 * 0.01, 1e-15);

  for (int step = 5; step < scene.time.steps; ++step) simulation.integrator().step(simulation.state());
  const Eigen::MatrixXd moved = simulation.method().embedded_displacement(simulation.state().displacement);
  // Each vertex on the cut against the nearest vertex of the surface before the cut on
  // its own side and on the other side.
  double gap = 0;
  int on_cut = 0;
  for (Eigen::Index v = 0; v < after.vertices.rows(); ++v) {
    if (std::abs(after.vertices(v, 0) - 0.55) > 1e-12) continue;
    ++on_cut;
    double own = 1e9, other = 1e9;
    Eigen::Index own_vertex = 0, other_vertex = 0;
    for (Eigen::Index w = 0; w < kept; ++w) {
      if (std::abs(before.vertices(w, 0) - 0.55) < 1e-12) continue;
      const double distance = (before.vertices.row(w) - after.vertices.row(v)).norm();
      double& nearest = piece_of[w] == piece_of[v] ? own : other;
      if (distance < nearest) {
        nearest = distance;
        (piece_of[w] == piece_of[v] ? own_vertex : other_vertex) = w;
      }
    }
    const double to_own = (moved.row(v) - moved.row(own_vertex)).norm();
    const double to_other = (moved.row(v) - moved.row(other_vertex)).norm();
    EXPECT_LT(to_own, 0.1 * to_other) << "vertex " << v << " at " << after.vertices.row(v);
    gap = std::max(gap, to_other);
  }
  EXPECT_GT(on_cut, 8);
  const double free_fall = 0.5 * 9.81 * 0.06 * 0.06;
  EXPECT_GT(gap, 0.5 * free_fall);
}

INSTANTIATE_TEST_SUITE_P(CuttingMethods, CutSurface, ::testing::Values("dg", "harmonic", "fcm", "fem"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

// A geometry given only as a volume mesh has no surface in common (Simulation cuts only a
// common one, once for every method): each method deforms its own mesh's boundary, open
// along the cut. dg and harmonic cut theirs, keeping its vertices' indices; fem and fcm take
// their cut tetrahedra's. A unit cube cut through at z = 0.5 opens into two closed halves.
class OwnSurfaceCut : public ::testing::TestWithParam<std::string> {};

TEST_P(OwnSurfaceCut, OpensIntoTwoClosedHalves) {
  const Scene scene = load_scene(scenes / "mesh_file_cut.json");
  const SceneGeometry geometry = load_scene_geometry(scene);
  ASSERT_EQ(geometry.common_surface(), nullptr);
  const MethodDescription& method = cli::find_method(GetParam());
  Simulation simulation(scene, geometry, GetParam(), method.factory, method.rebuild);
  const SurfaceMesh before = simulation.method().embedded_surface();
  simulation.apply(scene.events.at(0));
  const SurfaceMesh& after = simulation.method().embedded_surface();
  if (GetParam() == "dg" || GetParam() == "harmonic") {
    ASSERT_GT(after.vertices.rows(), before.vertices.rows());
    EXPECT_EQ(after.vertices.topRows(before.vertices.rows()), before.vertices);
  }
  const std::vector<int> piece_of = surface_vertex_pieces(after);
  const std::set<int> pieces(piece_of.begin(), piece_of.end());
  ASSERT_EQ(pieces.size(), 2u);
  for (const int piece : pieces) EXPECT_NEAR(piece_volume(after, piece_of, piece), 0.5, 1e-14);
}

INSTANTIATE_TEST_SUITE_P(EveryMethod, OwnSurfaceCut, ::testing::Values("dg", "harmonic", "fcm", "fem"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
}  // namespace altfem
