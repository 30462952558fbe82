// Convex clipping (shared/geometry/clip_convex.hpp): volumes of pieces against exact
// values, coincident faces and vertices decided exactly, and pieces of two cells that
// share a face adding up to the whole.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <random>

#include "shared/geometry/clip_convex.hpp"

namespace altfem {
namespace {

double volume(const std::vector<TetrahedronCorners>& pieces) {
  double sum = 0.0;
  for (const auto& piece : pieces) {
    const Eigen::Matrix3d edges = (piece.bottomRows<3>().rowwise() - piece.row(0)).transpose();
    EXPECT_GT(edges.determinant(), 0.0);
    sum += edges.determinant() / 6.0;
  }
  return sum;
}

Eigen::MatrixXd box_corners(const Eigen::Vector3d& low, const Eigen::Vector3d& high) {
  Eigen::MatrixXd corners(8, 3);
  corners << low.x(), low.y(), low.z(), high.x(), low.y(), low.z(), high.x(), high.y(), low.z(), low.x(), high.y(),
      low.z(), low.x(), low.y(), high.z(), high.x(), low.y(), high.z(), high.x(), high.y(), high.z(), low.x(), high.y(),
      high.z();
  return corners;
}

TetrahedronCorners tetrahedron(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                               const Eigen::Vector3d& d) {
  TetrahedronCorners t;
  t << a.transpose(), b.transpose(), c.transpose(), d.transpose();
  return t;
}

TEST(ClipConvex, TetrahedronInsideIsReturnedWhole) {
  const auto planes = hexahedron_clip_planes(box_corners(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()));
  const TetrahedronCorners t = tetrahedron({0.1, 0.1, 0.1}, {0.9, 0.1, 0.1}, {0.1, 0.9, 0.1}, {0.1, 0.1, 0.9});
  const auto pieces = clip_tetrahedron(t, planes);
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_EQ(pieces[0], t);
}

TEST(ClipConvex, FacesOnTheCellBoundaryCountOnceAcrossNeighbours) {
  // The unit corner tetrahedron, whose three faces lie in the planes x = 0, y = 0, z = 0,
  // against the cube [0,1]³ (kept whole) and its neighbours across those planes (nothing).
  const TetrahedronCorners t = tetrahedron({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1});
  EXPECT_DOUBLE_EQ(volume(clip_tetrahedron(t, hexahedron_clip_planes(box_corners({0, 0, 0}, {1, 1, 1})))), 1.0 / 6.0);
  EXPECT_TRUE(clip_tetrahedron(t, hexahedron_clip_planes(box_corners({-1, 0, 0}, {0, 1, 1}))).empty());
  EXPECT_TRUE(clip_tetrahedron(t, hexahedron_clip_planes(box_corners({0, -1, 0}, {1, 0, 1}))).empty());
  EXPECT_TRUE(clip_tetrahedron(t, hexahedron_clip_planes(box_corners({0, 0, -1}, {1, 1, 0}))).empty());
}

TEST(ClipConvex, CutThroughVerticesOnThePlane) {
  // The plane x = 0.5 through two vertices of the tetrahedron: both halves are exact.
  const TetrahedronCorners t = tetrahedron({0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, 0.5, 1});
  const double left = volume(clip_tetrahedron(t, hexahedron_clip_planes(box_corners({-1, -1, -1}, {0.5, 2, 2}))));
  const double right = volume(clip_tetrahedron(t, hexahedron_clip_planes(box_corners({0.5, -1, -1}, {2, 2, 2}))));
  EXPECT_NEAR(left, 1.0 / 12.0, 1e-16);
  EXPECT_NEAR(right, 1.0 / 12.0, 1e-16);
}

TEST(ClipConvex, CubeCutByTetrahedronPlanes) {
  // A tetrahedron containing the cube [0,1]³ clipped by ... the cube gives the cube.
  const TetrahedronCorners big = tetrahedron({-1, -1, -1}, {5, -1, -1}, {-1, 5, -1}, {-1, -1, 5});
  EXPECT_NEAR(volume(clip_tetrahedron(big, hexahedron_clip_planes(box_corners({0, 0, 0}, {1, 1, 1})))), 1.0, 1e-15);
  // The unit cube [0,1]³ as Kuhn tetrahedron clipped by the corner tetrahedron's planes.
  const auto corner_planes =
      tetrahedron_clip_planes((Eigen::MatrixXd(4, 3) << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1).finished());
  const TetrahedronCorners kuhn = tetrahedron({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1, 1, 1});
  // Its part with x + y + z <= 1 is the tetrahedron (0,0,0),(1,0,0),(1/2,1/2,0),(1/3,1/3,1/3).
  EXPECT_NEAR(volume(clip_tetrahedron(kuhn, corner_planes)), 1.0 / 36.0, 1e-16);
}

TEST(ClipConvex, VertexFanTilesThePieceWithFewerTetrahedra) {
  // The cube [0,1]³ cut out of a tetrahedron containing it: 6 square faces, 12 triangles.
  // The centroid's fan gives a tetrahedron per triangle, a corner's none for the 3 faces
  // through it; both tile the cube. A tetrahedron the planes do not cut stays whole.
  const auto planes = hexahedron_clip_planes(box_corners({0, 0, 0}, {1, 1, 1}));
  const TetrahedronCorners big = tetrahedron({-1, -1, -1}, {5, -1, -1}, {-1, 5, -1}, {-1, -1, 5});
  const auto centroid_pieces = clip_tetrahedron(big, planes, PieceFan::centroid);
  const auto vertex_pieces = clip_tetrahedron(big, planes, PieceFan::vertex);
  EXPECT_EQ(centroid_pieces.size(), 12u);
  EXPECT_EQ(vertex_pieces.size(), 6u);
  EXPECT_NEAR(volume(centroid_pieces), 1.0, 1e-15);
  EXPECT_NEAR(volume(vertex_pieces), 1.0, 1e-15);
  const TetrahedronCorners inside = tetrahedron({0.1, 0.1, 0.1}, {0.9, 0.1, 0.1}, {0.1, 0.9, 0.1}, {0.1, 0.1, 0.9});
  const auto whole = clip_tetrahedron(inside, planes, PieceFan::vertex);
  ASSERT_EQ(whole.size(), 1u);
  EXPECT_EQ(whole[0], inside);
  // Random cuts: the two fans' volumes agree to rounding.
  std::mt19937 generator(7);
  std::uniform_real_distribution<double> coordinate(-0.5, 1.5);
  const auto point = [&] {
    return Eigen::Vector3d(coordinate(generator), coordinate(generator), coordinate(generator));
  };
  for (int trial = 0; trial < 200; ++trial) {
    TetrahedronCorners t = tetrahedron(point(), point(), point(), point());
    const double centroid_volume = volume(clip_tetrahedron(t, planes, PieceFan::centroid));
    EXPECT_NEAR(volume(clip_tetrahedron(t, planes, PieceFan::vertex)), centroid_volume, 1e-14);
  }
}

TEST(ClipConvex, PiecesOfTwoNeighbouringCellsTileRandomTetrahedra) {
  // Seeded property test: two boxes sharing the face x = s, moved by a random rigid
  // motion with a random tetrahedron inside their union: the two clipped volumes add up
  // to the tetrahedron's.
  std::mt19937 generator(16);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 400; ++trial) {
    const Eigen::Matrix3d rotation =
        Eigen::AngleAxisd(6.3 * unit(generator), Eigen::Vector3d::Random().normalized()).toRotationMatrix();
    const Eigen::Vector3d shift = Eigen::Vector3d::Random();
    const double split = 0.2 + 0.6 * unit(generator);
    const auto moved = [&](Eigen::MatrixXd corners) {
      return Eigen::MatrixXd((corners * rotation.transpose()).rowwise() + shift.transpose());
    };
    const auto left = hexahedron_clip_planes(moved(box_corners({0, 0, 0}, {split, 1, 1})));
    const auto right = hexahedron_clip_planes(moved(box_corners({split, 0, 0}, {1, 1, 1})));
    TetrahedronCorners t;
    for (int c = 0; c < 4; ++c) {
      Eigen::Vector3d y(unit(generator), unit(generator), unit(generator));
      // In a third of the trials, vertices on the shared face (before the motion):
      // after rounding they are a hair in or out, the hard case for placing new vertices.
      if (trial % 3 == 0 && c < 3) y.x() = split;
      t.row(c) = (rotation * y + shift).transpose();
    }
    const Eigen::Matrix3d edges = (t.bottomRows<3>().rowwise() - t.row(0)).transpose();
    const double whole = std::abs(edges.determinant()) / 6.0;
    const double sum = volume(clip_tetrahedron(t, left)) + volume(clip_tetrahedron(t, right));
    EXPECT_NEAR(sum, whole, 1e-14) << "trial " << trial;
  }
}

// A corner a cut constructed on an edge of a grid's tetrahedral cell, rounded a few ulps
// off both planes through that edge (the ball cut out of fem's Tet10 cube: the cells'
// clipped volumes exceeded their own). The first plane used to cut a sliver of vertices
// a few ulps apart off that corner, the second to fold the piece through them: 1.04 times
// the tetrahedron's volume. Every other corner lies inside the cell, so the clip is the
// tetrahedron to a rounding.
TEST(ClipConvex, ACornerARoundingOffACellsEdgeClipsToTheTetrahedron) {
  const TetrahedronCorners inside = tetrahedron({0.51937231488346924, 0.40248513644275896, 0.097917172526512303},
                                                {0.51784785340480088, 0.35530135428012632, 0.10530135428012635},
                                                {0.5, 0.43015988766662938, 0.18015988766662935},
                                                {0.52167010733352459, 0.27167010733352454, 0.021670107333524567});
  Eigen::MatrixXd cell(4, 3);  // a cell of the 4³ grid split into six tetrahedra per cube
  cell << 0.5, 0.25, 0, 0.5, 0.5, 0, 0.5, 0.5, 0.25, 0.75, 0.5, 0.25;
  const Eigen::Matrix3d edges = (inside.bottomRows<3>().rowwise() - inside.row(0)).transpose();
  EXPECT_NEAR(volume(clip_tetrahedron(inside, tetrahedron_clip_planes(cell))), std::abs(edges.determinant()) / 6,
              1e-14 * std::abs(edges.determinant()));
  TetrahedronCorners moved = inside;
  moved(2, 2) = 0.18015988766662938;
  const Eigen::Matrix3d moved_edges = (moved.bottomRows<3>().rowwise() - moved.row(0)).transpose();
  EXPECT_NEAR(volume(clip_tetrahedron(moved, tetrahedron_clip_planes(cell))), std::abs(moved_edges.determinant()) / 6,
              1e-14 * std::abs(moved_edges.determinant()));
}

TEST(ClipConvex, PlanarityOfHexahedronFaces) {
  Eigen::MatrixXd corners = box_corners({0, 0, 0}, {1, 2, 3});
  EXPECT_TRUE(hexahedron_faces_planar(corners));
  corners(6, 2) += 1e-14;  // rounding-level: accepted
  EXPECT_TRUE(hexahedron_faces_planar(corners));
  corners(6, 2) += 1e-9;
  EXPECT_FALSE(hexahedron_faces_planar(corners));
  EXPECT_FALSE(hexahedron_faces_planar(box_corners({0, 0, 0}, {1, 2, 3}) + 1e-13 * Eigen::MatrixXd::Random(8, 3), 0.0));
}

}  // namespace
}  // namespace altfem
