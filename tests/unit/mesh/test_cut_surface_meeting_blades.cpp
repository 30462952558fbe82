// cut_surface (issue #33) after notches: finite blades that meet one another inside the
// body — an X and a T of two notches from the box's top, which open it along a cross and a
// T, and a V of two polygons that meet along their lower edges, which cuts a prism out —
// and blades that meet a notch after cuts it did not stop. A notch leaves its caps on one
// another, so a later blade cuts the box from before it again, with every blade since;
// every figure is exact: the caps cover the blades' parts inside, both sides.
#include <gtest/gtest.h>

#include "shared/mesh/cut_surface.hpp"
#include "tests/unit/mesh/surface_pieces.hpp"
#include "tests/unit/surfaces.hpp"

namespace altfem {
namespace {

using test::area_in_plane;

// The rectangle of the plane x = `x` (axis 0) or y = `x` (axis 1) over the other
// horizontal coordinate in [from, to] and z in [bottom, 2].
CuttingPlane vertical_blade(int axis, double x, double from, double to, double bottom) {
  const auto at = [&](double along, double z) {
    Eigen::Vector3d point(along, along, z);
    point(axis) = x;
    return point;
  };
  return polygon_blade({at(from, bottom), at(to, bottom), at(to, 2), at(from, 2)});
}

// How many vertices of `surface` lie at `point`: one per fan of triangles about it.
int copies_at(const SurfaceMesh& surface, const Eigen::Vector3d& point) {
  int copies = 0;
  for (Eigen::Index v = 0; v < surface.vertices.rows(); ++v) copies += surface.vertices.row(v) == point.transpose();
  return copies;
}

TEST(CutSurfaceByMeetingBlades, AnXAndATOfNotchesOpenTheBoxAlongBoth) {
  const SurfaceMesh box = test::box_surface(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  const CuttingPlane first = vertical_blade(0, 0.5, -1, 2, 0.5);
  const SurfaceMesh notched = cut_surface(box, first).surface;
  // The X: the second notch crosses the first; the T: it ends on the first's plane.
  for (const bool crossing : {true, false}) {
    const CuttingPlane second = vertical_blade(1, 0.5, crossing ? -1 : 0.5, 2, 0.5);
    const SurfaceCut cut = cut_surface(notched, second);
    EXPECT_EQ(cut.facts["pieces_left_whole"], 0) << crossing;
    EXPECT_EQ(cut.facts["blades_cut_again"], 1) << crossing;
    EXPECT_EQ(cut.surface.vertices.topRows(box.vertices.rows()), box.vertices) << crossing;
    const std::vector<double> volumes = test::closed_piece_volumes(cut.surface);
    ASSERT_EQ(volumes.size(), 1u) << crossing;
    EXPECT_NEAR(volumes[0], 1.0, 1e-15) << crossing;
    // Each notch's part inside, on both sides: ½ × 1 of the first, ½ × 1 or ½ × ½ of the second.
    EXPECT_NEAR(area_in_plane(cut.surface, 0.5, 0), 2 * 0.5, 1e-14) << crossing;
    EXPECT_NEAR(area_in_plane(cut.surface, 0.5, 1), 2 * (crossing ? 0.5 : 0.25), 1e-14) << crossing;
    // Where they meet on the top, the material falls into four corners (three for the T).
    EXPECT_EQ(copies_at(cut.surface, Eigen::Vector3d(0.5, 0.5, 1)), crossing ? 4 : 3) << crossing;
  }
}

TEST(CutSurfaceByMeetingBlades, AVOfTwoPolygonsCutsAPrismOut) {
  // Through (x, z) = (0.5, 0.5) up to x = 0.25 and 0.75 at z = 1: the prism over that
  // triangle, ½ · ½ · ½ in section and 1 long.
  const auto at = [](double x, double y, double z) { return Eigen::Vector3d(x, y, z); };
  const CuttingPlane left = polygon_blade({at(0.5, -1, 0.5), at(0.5, 2, 0.5), at(0.15, 2, 1.2), at(0.15, -1, 1.2)});
  const CuttingPlane right = polygon_blade({at(0.5, -1, 0.5), at(0.85, -1, 1.2), at(0.85, 2, 1.2), at(0.5, 2, 0.5)});
  const SurfaceMesh box = test::box_surface(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  const SurfaceCut cut = cut_surface(cut_surface(box, left).surface, right);
  EXPECT_EQ(cut.facts["pieces_left_whole"], 0);
  const std::vector<double> volumes = test::closed_piece_volumes(cut.surface);
  ASSERT_EQ(volumes.size(), 2u);
  EXPECT_NEAR(volumes[0], 0.125, 1e-15);
  EXPECT_NEAR(volumes[1], 0.875, 1e-15);
}

TEST(CutSurfaceByMeetingBlades, ABladeAfterACutTheNotchDidNotStopCutsFromBeforeTheNotch) {
  const SurfaceMesh box = test::box_surface(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  // A notch from the top down to z = 0.55, a plane below it, then a second notch beside it:
  // the plane left the surface notched, which the second notch found in one another.
  SurfaceMesh surface = cut_surface(box, vertical_blade(0, 0.2, -1, 2, 0.55)).surface;
  surface = cut_surface(surface, CuttingPlane(Eigen::Vector3d(0, 0, 0.25), Eigen::Vector3d::UnitZ())).surface;
  const SurfaceCut beside = cut_surface(surface, vertical_blade(0, 0.3, -1, 2, 0.6));
  EXPECT_EQ(beside.facts["pieces_left_whole"], 0);
  std::vector<double> volumes = test::closed_piece_volumes(beside.surface);
  ASSERT_EQ(volumes.size(), 2u);
  EXPECT_NEAR(volumes[0], 0.25, 1e-15);
  EXPECT_NEAR(volumes[1], 0.75, 1e-15);
  EXPECT_NEAR(area_in_plane(beside.surface, 0.2), 2 * 0.45, 1e-14);
  EXPECT_NEAR(area_in_plane(beside.surface, 0.3), 2 * 0.4, 1e-14);
  // A notch down to z = 0.2, a polygon through the whole box beside it, then a plane
  // across the notch: the left slice in two, the rest below the plane one piece (the notch
  // ends in it), above it two.
  surface = cut_surface(box, vertical_blade(0, 0.7, -1, 2, 0.2)).surface;
  surface = cut_surface(surface, vertical_blade(0, 0.3, -1, 2, -1)).surface;
  const SurfaceCut across = cut_surface(surface, CuttingPlane(Eigen::Vector3d(0, 0, 0.5), Eigen::Vector3d::UnitZ()));
  EXPECT_EQ(across.facts["pieces_left_whole"], 0);
  volumes = test::closed_piece_volumes(across.surface);
  ASSERT_EQ(volumes.size(), 5u);
  const std::vector<double> expected{0.15, 0.15, 0.15, 0.2, 0.35};
  for (std::size_t piece = 0; piece < expected.size(); ++piece) EXPECT_NEAR(volumes[piece], expected[piece], 1e-15);
}

}  // namespace
}  // namespace altfem
