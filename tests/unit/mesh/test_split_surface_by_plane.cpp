// cut_surface by a whole plane (split_surface_by_plane, issue #33): sections with holes,
// sections that touch themselves, and seeded degenerate planes. Every volume is exact: a
// cut moves no material.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "shared/mesh/cut_surface.hpp"
#include "tests/unit/mesh/seeded_cut_planes.hpp"
#include "tests/unit/mesh/surface_pieces.hpp"
#include "tests/unit/surfaces.hpp"

namespace altfem {
namespace {

using test::box_surface;
using test::closed_and_oriented;
using test::pieces_of;
using test::volume_of_closed_pieces;

// Each piece's Euler characteristic V − E + F: 2 for a sphere's topology, 0 for a torus's.
std::vector<int> euler_characteristics(const SurfaceMesh& surface) {
  std::vector<int> characteristics;
  for (const SurfaceMesh& piece : pieces_of(surface)) {
    std::set<int> vertices;
    std::set<std::pair<int, int>> edges;
    for (Eigen::Index t = 0; t < piece.triangles.rows(); ++t)
      for (int k = 0; k < 3; ++k) {
        vertices.insert(piece.triangles(t, k));
        edges.insert(std::minmax(piece.triangles(t, k), piece.triangles(t, (k + 1) % 3)));
      }
    characteristics.push_back(static_cast<int>(vertices.size() - edges.size()) +
                              static_cast<int>(piece.triangles.rows()));
  }
  return characteristics;
}

TEST(CutSurface, AFlatTorusCutAlongItsMiddleKeepsTheHoleOpenInBothCaps) {
  // The plane z = 0 holds a ring of the torus's vertices (sin 0 = 0) and crosses the
  // edges around the inner ring: each side's cap is an annulus, its hole the inner loop.
  // Both halves stay rings (χ = 0) and their volumes sum to the torus's.
  const SurfaceMesh torus = test::torus(1.0, 0.3, 24, 12, Eigen::Vector3d::Zero());
  const SurfaceCut cut = cut_surface(torus, CuttingPlane(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()));
  EXPECT_NEAR(volume_of_closed_pieces(cut.surface, 2), surface_volume(torus), 1e-14);
  EXPECT_EQ(euler_characteristics(cut.surface), (std::vector<int>{0, 0}));
}

// The side of the plane z = `height` each piece lies on, with the pieces' summed volumes.
std::map<int, double> volumes_by_side(const SurfaceMesh& surface, double height) {
  std::map<int, double> volume_of;
  for (const SurfaceMesh& piece : pieces_of(surface)) {
    EXPECT_TRUE(closed_and_oriented(piece));
    double z_sum = 0;
    int count = 0;
    for (Eigen::Index t = 0; t < piece.triangles.rows(); ++t)
      for (int k = 0; k < 3; ++k, ++count) z_sum += piece.vertices(piece.triangles(t, k), 2) - height;
    volume_of[z_sum > 0 ? +1 : -1] += surface_volume(piece);
  }
  return volume_of;
}

TEST(CutSurface, APlaneAlongAFaceOrThroughAValleyOfANonConvexBodyIsAnOrdinaryCut) {
  // An L-shaped prism cut by the plane of its foot's top face: that face bounds the foot
  // below. An M-shaped prism cut at its valley: the plane holds the valley's edge, the two
  // horns above touch along it (corefinement's clip gave one piece of the wrong volume).
  // Exact volumes on each side, every piece closed.
  const double length = 0.7;
  const SurfaceMesh l_shape = test::prism({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}},
                                          {{3, 0, 1}, {3, 1, 2}, {3, 4, 5}, {3, 5, 0}}, length);
  ASSERT_NEAR(surface_volume(l_shape), 3 * length, 1e-15);
  const CuttingPlane at_height_one(Eigen::Vector3d(0, 0, 1), Eigen::Vector3d::UnitZ());
  const std::map<int, double> l_sides = volumes_by_side(cut_surface(l_shape, at_height_one).surface, 1.0);
  EXPECT_NEAR(l_sides.at(-1), 2 * length, 1e-15);
  EXPECT_NEAR(l_sides.at(+1), 1 * length, 1e-15);

  const SurfaceMesh m_shape =
      test::prism({{0, 0}, {4, 0}, {4, 2}, {2, 1}, {0, 2}}, {{3, 4, 0}, {3, 0, 1}, {3, 1, 2}}, length);
  ASSERT_NEAR(surface_volume(m_shape), 6 * length, 1e-15);
  const SurfaceCut m_cut = cut_surface(m_shape, at_height_one);
  EXPECT_EQ(pieces_of(m_cut.surface).size(), 3u);  // the horns apart, the valley's edge once for each
  const std::map<int, double> m_sides = volumes_by_side(m_cut.surface, 1.0);
  EXPECT_NEAR(m_sides.at(-1), 4 * length, 1e-14);
  EXPECT_NEAR(m_sides.at(+1), 2 * length, 1e-14);
}

// Seeded planes of every degenerate kind (seeded_cut_planes.hpp) through the vertices of a
// box, a sphere, an L-shaped prism and a torus: 100 per surface (ALTFEM_CUT_PLANES sets
// the count). Each cut opens the piece or, grazing it, separates nothing; every piece is
// closed, oriented and of positive volume, and the volume is the surface's to 1e-12.
TEST(CutSurface, SeededPlanesThroughVerticesEdgesAndFacesGiveClosedPiecesOfTheSameVolume) {
  const std::vector<SurfaceMesh> surfaces = {box_surface(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()),
                                             test::sphere(0.5, 8, 16, Eigen::Vector3d::Constant(0.5)),
                                             test::prism({{0, 0}, {1, 0}, {1, 0.5}, {0.5, 0.5}, {0.5, 1}, {0, 1}},
                                                         {{3, 0, 1}, {3, 1, 2}, {3, 4, 5}, {3, 5, 0}}, 1.0),
                                             test::torus(0.3, 0.15, 16, 8, Eigen::Vector3d::Constant(0.5))};
  for (std::size_t s = 0; s < surfaces.size(); ++s) {
    const double volume = surface_volume(surfaces[s]);
    int opened = 0;
    for (const CuttingPlane& plane : seeded_cut_planes(surfaces[s].vertices, 100)) {
      const SurfaceCut cut = cut_surface(surfaces[s], plane);
      ASSERT_EQ(cut.facts["pieces_left_whole"], 0) << "surface " << s << ", plane through " << plane.point.transpose();
      double total = 0;
      for (const SurfaceMesh& piece : pieces_of(cut.surface)) {
        ASSERT_TRUE(closed_and_oriented(piece)) << "surface " << s << ", plane through " << plane.point.transpose();
        ASSERT_GT(surface_volume(piece), 0) << "surface " << s << ", plane through " << plane.point.transpose();
        total += surface_volume(piece);
      }
      EXPECT_NEAR(total, volume, 1e-12 * volume) << "surface " << s << ", plane through " << plane.point.transpose();
      opened += cut.facts["cap_triangles"].get<int>() > 0;
    }
    EXPECT_GT(opened, 50) << "surface " << s;  // most seeded planes cross the body
  }
}

}  // namespace
}  // namespace altfem
