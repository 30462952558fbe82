// Cells split by planes, the mesh kept conforming (Kaufmann et al. 2009 §9.3, Martin et
// al. 2008 §8): the pieces of a cell fill it exactly (their volumes sum to the cell's), every
// cell stays closed — a node a split puts on an edge is a node of every face holding it, so
// the unsplit neighbours' boundaries close over their hanging nodes — and planes through
// nodes, along edges and in faces are ordinary cases. Box children are checked against the
// exact octree: their nodes, faces and volumes.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

#include "shared/mesh/polyhedral_from_volume_mesh.hpp"
#include "shared/mesh/split_polyhedral_cells.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "tests/unit/mesh/every_cell_closed.hpp"
#include "tests/unit/mesh/unit_cube_mesh.hpp"

namespace altfem {
namespace {

// The 1→8 split: the three coordinate planes through the cell's centroid.
CellSplit eighths(const PolyhedralMesh& mesh, int cell) {
  const Eigen::Vector3d centre = mesh.cell_centroids.row(cell);
  return {cell,
          {plane_through(centre, Eigen::Vector3d::UnitX()), plane_through(centre, Eigen::Vector3d::UnitY()),
           plane_through(centre, Eigen::Vector3d::UnitZ())}};
}

// Each input cell's pieces fill it: their volumes sum to its volume, every one positive.
::testing::AssertionResult pieces_fill_their_cells(const PolyhedralMesh& before, const SplitCells& split) {
  Eigen::VectorXd filled = Eigen::VectorXd::Zero(before.cell_count());
  for (int cell = 0; cell < split.mesh.cell_count(); ++cell) {
    if (!(split.mesh.cell_volumes[cell] > 0))
      return ::testing::AssertionFailure() << "piece " << cell << " has volume " << split.mesh.cell_volumes[cell];
    filled[split.parent_cell[cell]] += split.mesh.cell_volumes[cell];
  }
  for (int cell = 0; cell < before.cell_count(); ++cell)
    if (std::abs(filled[cell] - before.cell_volumes[cell]) > 1e-13 * before.cell_volumes[cell])
      return ::testing::AssertionFailure()
             << "cell " << cell << ": pieces fill " << filled[cell] << " of " << before.cell_volumes[cell];
  return ::testing::AssertionSuccess();
}

TEST(SplitPolyhedralCells, OneBoxInEightIsTheOctreeOfItsCorners) {
  const PolyhedralMesh mesh = unit_cube_mesh(ElementType::hex8, 1);
  const SplitCells split = split_polyhedral_cells(mesh, {eighths(mesh, 0)});
  EXPECT_EQ(split.mesh.cell_count(), 8);
  EXPECT_EQ(split.mesh.nodes.rows(), 27);
  EXPECT_EQ(split.new_nodes, 19);
  EXPECT_EQ(split.hanging_nodes, 0);
  int interior = 0;
  for (int face = 0; face < split.mesh.face_count(); ++face) interior += !split.mesh.is_boundary_face(face);
  EXPECT_EQ(interior, 12);  // each mid-plane's square in four
  EXPECT_EQ(split.mesh.face_count() - interior, 24);
  for (int cell = 0; cell < 8; ++cell) {
    EXPECT_EQ(split.mesh.cell_volumes[cell], 0.125);  // halving is exact in binary
    EXPECT_EQ(split.mesh.cell_kinds[cell], PolyhedralCellKind::hexahedron);
    EXPECT_EQ(split.parent_cell[cell], 0);
  }
  for (Eigen::Index node = 0; node < split.mesh.nodes.rows(); ++node)
    for (int axis = 0; axis < 3; ++axis) {
      const double x = split.mesh.nodes(node, axis);
      EXPECT_TRUE(x == 0 || x == 0.5 || x == 1) << "node " << node << " at " << split.mesh.nodes.row(node);
    }
  EXPECT_TRUE(every_cell_closed(split.mesh));
}

TEST(SplitPolyhedralCells, AnUnsplitNeighbourHoldsTheNewNodesOnItsFacesAndEdges) {
  const PolyhedralMesh mesh = unit_cube_mesh(ElementType::hex8, 2);
  const SplitCells split = split_polyhedral_cells(mesh, {eighths(mesh, 0)});
  EXPECT_EQ(split.mesh.cell_count(), 15);
  EXPECT_EQ(split.new_nodes, 19);
  // 9 of the corner cell's 12 edges and 3 of its faces are shared with a neighbour.
  EXPECT_EQ(split.hanging_nodes, 12);
  EXPECT_TRUE(every_cell_closed(split.mesh));
  EXPECT_TRUE(pieces_fill_their_cells(mesh, split));
  EXPECT_NEAR(split.mesh.cell_volumes.sum(), 1.0, 1e-15);
  for (int cell = 1; cell < 8; ++cell) {
    EXPECT_EQ(split.parent_cell[cell], cell);
    EXPECT_EQ(split.mesh.cell_volumes[cell], 0.125);
  }
}

TEST(SplitPolyhedralCells, NeighboursSplitTogetherShareTheirMidPlanes) {
  const PolyhedralMesh mesh = polyhedral_mesh_from_volume_mesh(
      structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d(2, 1, 1)), Eigen::Vector3i(2, 1, 1),
                      ElementType::hex8));
  const SplitCells split = split_polyhedral_cells(mesh, {eighths(mesh, 0), eighths(mesh, 1)});
  EXPECT_EQ(split.mesh.cell_count(), 16);
  EXPECT_EQ(split.mesh.nodes.rows(), 5 * 3 * 3);  // the 4 × 2 × 2 grid's
  EXPECT_EQ(split.hanging_nodes, 0);
  EXPECT_TRUE(every_cell_closed(split.mesh));
  EXPECT_TRUE(pieces_fill_their_cells(mesh, split));
}

TEST(SplitPolyhedralCells, AChildSplitAgainLeavesHangingNodesOnItsSiblings) {
  const PolyhedralMesh mesh = unit_cube_mesh(ElementType::hex8, 1);
  const SplitCells once = split_polyhedral_cells(mesh, {eighths(mesh, 0)});
  const SplitCells twice = split_polyhedral_cells(once.mesh, {eighths(once.mesh, 3)});
  EXPECT_EQ(twice.mesh.cell_count(), 15);
  EXPECT_EQ(twice.hanging_nodes, 12);
  EXPECT_TRUE(every_cell_closed(twice.mesh));
  EXPECT_TRUE(pieces_fill_their_cells(once.mesh, twice));
}

TEST(SplitPolyhedralCells, APlaneThroughAnEdgeAndNodesHalvesABox) {
  const PolyhedralMesh mesh = unit_cube_mesh(ElementType::hex8, 1);
  // x = y holds the box's two vertical edges at (0, 0) and (1, 1).
  const SplitCells split =
      split_polyhedral_cells(mesh, {{0, {plane_through(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, -1, 0))}}});
  EXPECT_EQ(split.mesh.cell_count(), 2);
  EXPECT_EQ(split.new_nodes, 0);
  EXPECT_EQ(split.mesh.cell_volumes[0], 0.5);
  EXPECT_EQ(split.mesh.cell_volumes[1], 0.5);
  EXPECT_EQ(split.mesh.cell_kinds[0], PolyhedralCellKind::refined);
  EXPECT_TRUE(every_cell_closed(split.mesh));
}

TEST(SplitPolyhedralCells, PlanesThroughTheCellsAtRandomKeepEveryCellClosedAndFilled) {
  // Tetrahedra and boxes, any 1 to 3 planes through any inside point, twice in a row.
  std::mt19937 random(33);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (const ElementType type : {ElementType::tet4, ElementType::hex8})
    for (int trial = 0; trial < 20; ++trial) {
      PolyhedralMesh mesh = unit_cube_mesh(type, 2);
      for (int round = 0; round < 2; ++round) {
        std::vector<CellSplit> splits;
        for (int cell = 0; cell < mesh.cell_count(); ++cell) {
          if (random() % 3 != 0) continue;
          const int plane_count = 1 + static_cast<int>(random() % 3);
          // A point near the centroid: any inside point would do, the centroid keeps the pieces fat.
          const Eigen::Vector3d point =
              mesh.cell_centroids.row(cell).transpose() +
              0.1 * mesh.cell_diameters[cell] * Eigen::Vector3d(uniform(random), uniform(random), uniform(random));
          CellSplit split{cell, {}};
          for (int k = 0; k < plane_count; ++k)
            split.planes.push_back(
                plane_through(point, Eigen::Vector3d(uniform(random), uniform(random), uniform(random))));
          splits.push_back(split);
        }
        const SplitCells split = split_polyhedral_cells(mesh, splits);
        ASSERT_TRUE(every_cell_closed(split.mesh)) << "trial " << trial << ", round " << round;
        ASSERT_TRUE(pieces_fill_their_cells(mesh, split)) << "trial " << trial << ", round " << round;
        mesh = split.mesh;
      }
    }
}

TEST(SplitPolyhedralCells, RefusesACellTwiceNoPlaneOrAZeroNormal) {
  const PolyhedralMesh mesh = unit_cube_mesh(ElementType::hex8, 1);
  EXPECT_THROW(split_polyhedral_cells(mesh, {eighths(mesh, 0), eighths(mesh, 0)}), std::invalid_argument);
  EXPECT_THROW(split_polyhedral_cells(mesh, {{0, {}}}), std::invalid_argument);
  EXPECT_THROW(split_polyhedral_cells(mesh, {{0, {{Eigen::Vector3d::Zero(), 0.5}}}}), std::invalid_argument);
  EXPECT_THROW(split_polyhedral_cells(mesh, {{1, {plane_through(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX())}}}),
               std::invalid_argument);
}

}  // namespace
}  // namespace altfem

namespace altfem {
namespace {

// Two neighbours split 1→2 by planes normal to principal directions a rounding apart: they
// cross the edges the neighbours share at points a few ulps apart, which are one node (the
// snap), not two with faces a few ulps wide between them.
TEST(SplitPolyhedralCells, NearlyEqualPlanesOfNeighboursMakeOneNodePerSharedEdge) {
  const PolyhedralMesh mesh = polyhedral_mesh_from_volume_mesh(
      structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 2, 1)),
                      Eigen::Vector3d(1, 2, 1).cast<int>(), ElementType::hex8));
  const Eigen::Vector3d tilted = Eigen::Vector3d(1, 0.2, 0.1).normalized();
  const Eigen::Vector3d tilted_again = (tilted + Eigen::Vector3d(0, 3e-16, -2e-16)).normalized();
  const SplitCells split = split_polyhedral_cells(
      mesh,
      {{0, {plane_through(mesh.cell_centroids.row(0), tilted)}},
       {1, {plane_through(mesh.cell_centroids.row(0).transpose() + Eigen::Vector3d(0, 1e-16, 0), tilted_again)}}});
  // The two planes cross the 4 + 4 edges along x of the two boxes, 2 of them shared: 6 nodes.
  EXPECT_EQ(split.new_nodes, 6);
  EXPECT_EQ(split.mesh.cell_count(), 4);
  EXPECT_TRUE(every_cell_closed(split.mesh));
  EXPECT_TRUE(pieces_fill_their_cells(mesh, split));
  EXPECT_GT(split.mesh.cell_volumes.minCoeff(), 0.1);
}

}  // namespace
}  // namespace altfem
