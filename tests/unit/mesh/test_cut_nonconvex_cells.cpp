// Non-convex cells cut by a blade (Kaufmann et al. 2009 §9.4 keep non-convex pieces): a
// side of a cell may fall into several pieces, a face into several polygons and a section
// into several caps. Checked on prisms over a U and an L, whose pieces' volumes are known,
// with blades through both arms, in the plane of a reflex face and through a reflex edge;
// and on a sliced torus (cut cells, non-convex ones among them) under seeded planes of
// every degenerate kind, against the volume on each side computed independently by
// clipping each cell's signed tetrahedra.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "shared/geometry/clip_convex.hpp"
#include "shared/mesh/cut_polyhedral_mesh.hpp"
#include "shared/mesh/planar_loops.hpp"
#include "shared/mesh/slice_into_polyhedra.hpp"
#include "tests/unit/mesh/every_cell_closed.hpp"
#include "tests/unit/mesh/seeded_cut_planes.hpp"
#include "tests/unit/surfaces.hpp"

namespace altfem {
namespace {

// One cell: the prism over the counter-clockwise polygon `outline` (x, y), z in [0, 1].
PolyhedralMesh prism_cell(const std::vector<Eigen::Vector2d>& outline) {
  const int n = static_cast<int>(outline.size());
  PolyhedralMesh mesh;
  mesh.nodes.resize(2 * n, 3);
  for (int k = 0; k < n; ++k) {
    mesh.nodes.row(k) << outline[k].x(), outline[k].y(), 0;
    mesh.nodes.row(n + k) << outline[k].x(), outline[k].y(), 1;
  }
  std::vector<int> bottom, top;
  for (int k = 0; k < n; ++k) {
    bottom.push_back(n - 1 - k);
    top.push_back(n + k);
  }
  mesh.faces = {bottom, top};
  for (int k = 0; k < n; ++k) mesh.faces.push_back({k, (k + 1) % n, n + (k + 1) % n, n + k});
  mesh.face_cells = Eigen::MatrixXi::Constant(n + 2, 2, -1);
  mesh.face_cells.col(0).setZero();
  mesh.cell_faces = {std::vector<int>(n + 2)};
  std::iota(mesh.cell_faces[0].begin(), mesh.cell_faces[0].end(), 0);
  mesh.cell_kinds = {PolyhedralCellKind::cut};
  compute_polyhedral_geometry(mesh);
  return mesh;
}

// [0,3]×[0,2] without [1,2]×[1,2]: area 5.
const std::vector<Eigen::Vector2d> u_shape{{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
// [0,2]×[0,1] and [0,1]×[1,2]: area 3, its reflex corner at (1, 1).
const std::vector<Eigen::Vector2d> l_shape{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};

std::vector<double> sorted_volumes(const PolyhedralMesh& mesh) {
  std::vector<double> volumes(mesh.cell_volumes.data(), mesh.cell_volumes.data() + mesh.cell_count());
  std::sort(volumes.begin(), volumes.end());
  return volumes;
}

void expect_volumes(const PolyhedralMesh& mesh, const std::vector<double>& expected) {
  const std::vector<double> volumes = sorted_volumes(mesh);
  ASSERT_EQ(volumes.size(), expected.size());
  for (std::size_t k = 0; k < volumes.size(); ++k) EXPECT_NEAR(volumes[k], expected[k], 1e-14) << k;
}

TEST(SplitPolygonByPlane, AUThroughBothArmsGivesTwoPiecesAboveAndOneBelow) {
  std::vector<Eigen::Vector3d> positions;
  for (const Eigen::Vector2d& corner : u_shape) positions.emplace_back(corner.x(), corner.y(), 0);
  // The line y = 1.5 crosses the four vertical edges of the arms: crossing nodes go in.
  std::vector<int> loop;
  std::vector<int> side;
  for (int k = 0; k < 8; ++k) {
    loop.push_back(k);
    side.push_back(positions[k].y() > 1.5 ? +1 : -1);
    const Eigen::Vector3d& p = positions[k];
    const Eigen::Vector3d& q = positions[(k + 1) % 8];
    if ((p.y() - 1.5) * (q.y() - 1.5) < 0) {
      positions.push_back(p + (1.5 - p.y()) / (q.y() - p.y()) * (q - p));
      loop.push_back(static_cast<int>(positions.size()) - 1);
    }
  }
  side.resize(positions.size(), 0);
  const std::vector<PolygonPiece> pieces = split_polygon_by_plane(loop, positions, side, Eigen::Vector3d::UnitY());
  ASSERT_EQ(pieces.size(), 3u);
  int above = 0;
  double area = 0;
  for (const PolygonPiece& piece : pieces) {
    above += piece.side > 0;
    for (std::size_t k = 0; k < piece.loop.size(); ++k)
      area += positions[piece.loop[k]].cross(positions[piece.loop[(k + 1) % piece.loop.size()]]).z() / 2;
  }
  EXPECT_EQ(above, 2);
  EXPECT_NEAR(area, 5.0, 1e-15);
}

TEST(CutNonConvexCells, APlaneThroughBothArmsOfAUGivesTwoPiecesOnOneSide) {
  const PolyhedralCut cut =
      cut_polyhedral_mesh(prism_cell(u_shape), {Eigen::Vector3d(0, 1.5, 0), Eigen::Vector3d::UnitY()});
  EXPECT_EQ(cut.crossed_cells, 1);
  EXPECT_TRUE(every_cell_closed(cut.mesh));
  expect_volumes(cut.mesh, {0.5, 0.5, 4.0});
  for (const PolyhedralCellKind kind : cut.mesh.cell_kinds) EXPECT_EQ(kind, PolyhedralCellKind::cut);
  // The arms lie apart: they share no node with each other or with the base.
  EXPECT_EQ(cut.duplicated_nodes, 8);
}

TEST(CutNonConvexCells, APlaneInAReflexFaceLeavesThatFaceToTheSideItBounds) {
  const PolyhedralCut cut =
      cut_polyhedral_mesh(prism_cell(u_shape), {Eigen::Vector3d(0, 1, 0), Eigen::Vector3d::UnitY()});
  EXPECT_TRUE(every_cell_closed(cut.mesh));
  expect_volumes(cut.mesh, {1.0, 1.0, 3.0});
}

TEST(CutNonConvexCells, APlaneThroughTheReflexEdgeOfAnLCutsItsCornersOff) {
  // x + y = 2 runs through the reflex edge and the outer corners (2, 0) and (0, 2): the
  // corners beyond it are two triangular prisms that meet only along that edge, so they
  // stay one piece, closed, as the edge's four faces pair up.
  const PolyhedralCut cut =
      cut_polyhedral_mesh(prism_cell(l_shape), {Eigen::Vector3d(1, 1, 0), Eigen::Vector3d(1, 1, 0)});
  EXPECT_TRUE(every_cell_closed(cut.mesh));
  expect_volumes(cut.mesh, {1.0, 2.0});
  // Just off the edge (x + y = 2.1) the corners are apart: two triangular prisms with
  // legs 0.9 (volume 0.405 each), and the rest.
  const PolyhedralCut off =
      cut_polyhedral_mesh(prism_cell(l_shape), {Eigen::Vector3d(1.1, 1, 0), Eigen::Vector3d(1, 1, 0)});
  EXPECT_TRUE(every_cell_closed(off.mesh));
  expect_volumes(off.mesh, {0.405, 0.405, 2.19});
}

// The volume of `cell` on the positive side of `plane`, from its fan of signed
// tetrahedra (each face's fan from its first node, apexed at the cell's first node)
// clipped by the plane: exact for non-convex cells, and independent of the cut.
double cell_volume_on_positive_side(const PolyhedralMesh& mesh, int cell, const CuttingPlane& plane) {
  Eigen::Index largest = 0;
  plane.normal.cwiseAbs().maxCoeff(&largest);
  const Eigen::Vector3d first = plane.normal.cross(Eigen::Vector3d::Unit((largest + 1) % 3));
  const ClipPlane clip{plane.point, plane.point + plane.normal.cross(first), plane.point + first};
  const auto signed_volume = [](const TetrahedronCorners& t) {
    return (t.row(1) - t.row(0)).cross(t.row(2) - t.row(0)).dot(t.row(3) - t.row(0)) / 6;
  };
  const Eigen::RowVector3d apex = mesh.nodes.row(mesh.faces[mesh.cell_faces[cell][0]][0]);
  double volume = 0;
  for (const int face : mesh.cell_faces[cell]) {
    std::vector<int> loop = mesh.faces[face];
    if (mesh.face_cells(face, 0) != cell) std::reverse(loop.begin(), loop.end());
    for (std::size_t k = 1; k + 1 < loop.size(); ++k) {
      TetrahedronCorners tetrahedron;
      tetrahedron << apex, mesh.nodes.row(loop[0]), mesh.nodes.row(loop[k]), mesh.nodes.row(loop[k + 1]);
      const double sign = signed_volume(tetrahedron) < 0 ? -1 : 1;
      for (const TetrahedronCorners& piece : clip_tetrahedron(tetrahedron, {clip}))
        volume += sign * std::abs(signed_volume(piece));
    }
  }
  return volume;
}

// Seeded planes of every degenerate kind through a sliced torus, and finite blades in
// them (whose pieces beyond the blade's edge stay joined): every piece closed with
// positive volume, the volume kept, no piece on both sides, and the pieces on the
// positive side holding what clipping the uncut cells leaves there.
// One cell that is a square ring around the z axis through (1.5, 1.5): [0,3]² without
// [1,2]², z in [0, 1], volume 8; its top and bottom are 4 trapezoids each (a face has no hole).
PolyhedralMesh ring_cell() {
  const std::vector<Eigen::Vector2d> outer{{0, 0}, {3, 0}, {3, 3}, {0, 3}}, inner{{1, 1}, {2, 1}, {2, 2}, {1, 2}};
  PolyhedralMesh mesh;
  mesh.nodes.resize(16, 3);
  for (int k = 0; k < 4; ++k)
    for (int level = 0; level < 2; ++level) {
      mesh.nodes.row(8 * level + k) << outer[k].x(), outer[k].y(), level;
      mesh.nodes.row(8 * level + 4 + k) << inner[k].x(), inner[k].y(), level;
    }
  for (int k = 0; k < 4; ++k) {
    const int next = (k + 1) % 4;
    mesh.faces.push_back({k, next, 8 + next, 8 + k});            // outer side, out
    mesh.faces.push_back({4 + next, 4 + k, 12 + k, 12 + next});  // inner side, into the hole
    mesh.faces.push_back({4 + k, 4 + next, next, k});            // bottom trapezoid, down
    mesh.faces.push_back({8 + k, 8 + next, 12 + next, 12 + k});  // top trapezoid, up
  }
  mesh.face_cells = Eigen::MatrixXi::Constant(16, 2, -1);
  mesh.face_cells.col(0).setZero();
  mesh.cell_faces = {std::vector<int>(16)};
  std::iota(mesh.cell_faces[0].begin(), mesh.cell_faces[0].end(), 0);
  mesh.cell_kinds = {PolyhedralCellKind::cut};
  compute_polyhedral_geometry(mesh);
  return mesh;
}

// A blade through the ring all round: each side's section is an annulus, a cap with a hole,
// which becomes simple polygons bridged to the outer loop; the two rings come apart whole.
// Through the centre of symmetry the sides have equal volumes, level or tilted.
TEST(CutNonConvexCells, ASectionWithAHoleBecomesCapsWithoutOne) {
  const PolyhedralMesh ring = ring_cell();
  ASSERT_NEAR(ring.cell_volumes.sum(), 8.0, 1e-14);
  for (const Eigen::Vector3d& normal : {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0.1, -0.2, 1)}) {
    PolyhedralCut cut;
    ASSERT_NO_THROW(cut = cut_polyhedral_mesh(ring, {Eigen::Vector3d(1.5, 1.5, 0.5), normal}));
    EXPECT_EQ(cut.crossed_cells, 1);
    EXPECT_TRUE(every_cell_closed(cut.mesh));
    expect_volumes(cut.mesh, {4.0, 4.0});
    for (int face = 0; face < cut.mesh.face_count(); ++face) EXPECT_TRUE(cut.mesh.is_boundary_face(face));
  }
}

TEST(CutNonConvexCells, SeededPlanesThroughASlicedTorusGiveClosedPiecesEachOnOneSide) {
  SlicingOptions options;
  options.resolution = 6;
  const PolyhedralMesh mesh =
      slice_into_polyhedra(test::torus(1.0, 0.4, 48, 24, Eigen::Vector3d::Zero()), options).mesh;
  const double volume = mesh.cell_volumes.sum();
  int nonconvex_crossed = 0;
  std::vector<CuttingPlane> blades = seeded_cut_planes(mesh.nodes, 50);
  for (const CuttingPlane& polygon : seeded_cut_polygons(mesh.nodes, 0.4, 50)) blades.push_back(polygon);
  for (const CuttingPlane& plane : blades) {
    SCOPED_TRACE(::testing::Message() << "point " << plane.point.transpose() << ", normal "
                                      << plane.normal.transpose());
    PolyhedralCut cut;
    ASSERT_NO_THROW(cut = cut_polyhedral_mesh(mesh, plane));
    ASSERT_TRUE(every_cell_closed(cut.mesh));
    ASSERT_GT(cut.mesh.cell_volumes.minCoeff(), 0.0);
    EXPECT_NEAR(cut.mesh.cell_volumes.sum(), volume, 1e-13 * volume);
    // A finite blade leaves whole the cells beyond its edge that the plane crosses.
    const bool whole_plane = plane.polygon.empty();
    double expected_positive = 0, positive = 0;
    for (int cell = 0; cell < mesh.cell_count(); ++cell)
      expected_positive += cell_volume_on_positive_side(mesh, cell, plane);
    for (int cell = 0; cell < cut.mesh.cell_count(); ++cell) {
      const bool split = std::count(cut.parent_cell.begin(), cut.parent_cell.end(), cut.parent_cell[cell]) > 1;
      const double piece_positive = cell_volume_on_positive_side(cut.mesh, cell, plane);
      const double piece = cut.mesh.cell_volumes[cell];
      if (whole_plane || split) {
        ASSERT_TRUE(piece_positive < 1e-12 * volume || piece_positive > piece - 1e-12 * volume) << "piece " << cell;
      }
      if (piece_positive > piece / 2) positive += piece;
      nonconvex_crossed += split && cut.mesh.cell_kinds[cell] == PolyhedralCellKind::cut;
    }
    if (whole_plane) {
      EXPECT_NEAR(positive, expected_positive, 1e-12 * volume);
    }
  }
  EXPECT_GT(nonconvex_crossed, 50);
}

// The 1503rd seeded finite blade grazes the torus's bottom 3e-12 above its lowest
// nodes: one piece is thinner than round-off, its rounded volume not positive. It is
// merged into the piece across its largest face; the rest is as for any blade.
TEST(CutNonConvexCells, APieceThinnerThanRoundOffIsMergedIntoItsNeighbour) {
  SlicingOptions options;
  options.resolution = 6;
  const PolyhedralMesh mesh =
      slice_into_polyhedra(test::torus(1.0, 0.4, 48, 24, Eigen::Vector3d::Zero()), options).mesh;
  const CuttingPlane blade = seeded_cut_polygons(mesh.nodes, 0.4, 1503).back();
  PolyhedralCut cut;
  ASSERT_NO_THROW(cut = cut_polyhedral_mesh(mesh, blade));
  EXPECT_EQ(cut.merged_pieces, 1);
  EXPECT_TRUE(every_cell_closed(cut.mesh));
  EXPECT_GT(cut.mesh.cell_volumes.minCoeff(), 0.0);
  EXPECT_NEAR(cut.mesh.cell_volumes.sum(), mesh.cell_volumes.sum(), 1e-13 * mesh.cell_volumes.sum());
  ASSERT_TRUE(every_node_at_its_source(mesh.nodes, cut));
}

}  // namespace
}  // namespace altfem
