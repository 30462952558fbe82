// The hexahedral forest fem refines (hexahedral_forest.hpp): split cells, 2:1 balance, and
// hanging nodes whose constraints reproduce every polynomial of the element type, so that
// the constrained space is conforming and holds the coarse one.
#include <gtest/gtest.h>

#include <cmath>

#include "shared/mesh/hexahedral_forest.hpp"
#include "shared/mesh/structured_grid.hpp"

namespace altfem {
namespace {

const Eigen::AlignedBox3d unit_box(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());

TEST(HexahedralForest, TheUnsplitGridIsStructuredGridNodeForNode) {
  for (const ElementType type : {ElementType::hex8, ElementType::hex27}) {
    const Eigen::AlignedBox3d box(Eigen::Vector3d(-1, 0, 0.5), Eigen::Vector3d(2, 0.3, 0.9));
    const Eigen::Vector3i resolution(5, 3, 2);
    const ConstrainedHexahedralMesh forest = forest_mesh(grid_forest(box, resolution, type));
    const VolumeMesh grid = structured_grid(box, resolution, type);
    EXPECT_TRUE(forest.constraints.empty());
    ASSERT_EQ(forest.mesh.cells.rows(), grid.cells.rows());
    ASSERT_EQ(forest.mesh.nodes.rows(), grid.nodes.rows());
    for (Eigen::Index cell = 0; cell < grid.cells.rows(); ++cell)
      for (Eigen::Index a = 0; a < grid.cells.cols(); ++a)
        EXPECT_LE((forest.mesh.nodes.row(forest.mesh.cells(cell, a)) - grid.nodes.row(grid.cells(cell, a))).norm(),
                  1e-15);
  }
}

// The middle cell of a 3 × 3 × 3 grid split: of its children's 27 nodes, the 8 corners are
// the grid's, the centre is free, the 6 face centres hang on the face neighbours (4 corners,
// ¼ each) and the 12 edge midpoints on the edge neighbours (2 corners, ½ each).
TEST(HexahedralForest, ASplitCellsNodesHangOnItsCoarseNeighbours) {
  const HexahedralForest grid = grid_forest(unit_box, Eigen::Vector3i::Constant(3), ElementType::hex8);
  int balancing = -1;
  const HexahedralForest split = refine_forest(grid, {13}, &balancing);
  EXPECT_EQ(balancing, 0);
  EXPECT_EQ(split.leaf_count(), 26 + 8);
  const ConstrainedHexahedralMesh mesh = forest_mesh(split);
  EXPECT_EQ(mesh.constraints.free_nodes, 64 + 1);
  ASSERT_EQ(mesh.constraints.hanging_nodes(), 18);
  int on_faces = 0, on_edges = 0;
  for (int i = 0; i < 18; ++i) {
    const std::vector<double>& weights = mesh.constraints.weights[i];
    const double each = weights.size() == 4 ? 0.25 : 0.5;
    (weights.size() == 4 ? on_faces : on_edges) += 1;
    for (const double weight : weights) EXPECT_NEAR(weight, each, 1e-15);
  }
  EXPECT_EQ(on_faces, 6);
  EXPECT_EQ(on_edges, 12);
}

// A field of the element's own space (trilinear for Hex8, serendipity quadratic for Hex20,
// triquadratic for Hex27), taken at the free nodes, is exact at every hanging node, after
// splits two levels deep.
TEST(HexahedralForest, HangingNodesInterpolateTheTypesPolynomialsExactly) {
  const auto trilinear = [](const Eigen::Vector3d& x) {
    return 1 + x.x() - 2 * x.y() * x.z() + 3 * x.x() * x.y() * x.z();
  };
  const auto quadratic = [](const Eigen::Vector3d& x) {
    return x.x() * x.x() - x.y() * x.z() + 2 * x.z() * x.z() + x.x() * x.x() * x.y();  // x²y: serendipity has it
  };
  const auto triquadratic = [](const Eigen::Vector3d& x) {
    return x.x() * x.x() * x.y() * x.y() * x.z() * x.z() - x.x() * x.y() + 0.5;
  };
  for (const ElementType type : {ElementType::hex8, ElementType::hex20, ElementType::hex27}) {
    SCOPED_TRACE(element_name(type));
    const auto field = [&](const Eigen::Vector3d& x) {
      return type == ElementType::hex8 ? trilinear(x) : type == ElementType::hex20 ? quadratic(x) : triquadratic(x);
    };
    HexahedralForest forest = grid_forest(unit_box, Eigen::Vector3i(3, 2, 2), type);
    forest = refine_forest(forest, {0, 4});
    forest = refine_forest(forest, {7});  // the first cell's child at the grid's inside
    const ConstrainedHexahedralMesh mesh = forest_mesh(forest);
    ASSERT_GT(mesh.constraints.hanging_nodes(), 0);
    for (int i = 0; i < mesh.constraints.hanging_nodes(); ++i) {
      double value = 0;
      for (std::size_t k = 0; k < mesh.constraints.masters[i].size(); ++k) {
        const int master = mesh.constraints.masters[i][k];
        ASSERT_LT(master, mesh.constraints.free_nodes);
        value += mesh.constraints.weights[i][k] * field(mesh.mesh.nodes.row(master).transpose());
      }
      EXPECT_NEAR(value, field(mesh.mesh.nodes.row(mesh.constraints.free_nodes + i).transpose()), 1e-13);
    }
  }
}

// A 2 × 2 × 2 grid whose first cell's inner child is split again: the level-2 leaves touch
// cells 1, 2 and 4 across faces and 3, 5 and 6 across edges, which the balance splits; cell 7
// touches them at a corner only and stays.
TEST(HexahedralForest, TheBalanceSplitsFaceAndEdgeNeighboursTwoLevelsCoarser) {
  HexahedralForest forest = grid_forest(unit_box, Eigen::Vector3i::Constant(2), ElementType::hex8);
  forest = refine_forest(forest, {0});
  int balancing = -1;
  forest = refine_forest(forest, {7}, &balancing);
  EXPECT_EQ(balancing, 6);
  EXPECT_EQ(forest.leaf_count(), 7 + 8 + 6 * 8 + 1);
  for (const ForestFace& face : forest_interior_faces(forest))
    EXPECT_LE(std::abs(forest.levels[face.first] - forest.levels[face.second]), 1);
}

// The faces between leaves tile each grid face once: a 2 × 1 × 1 grid with its first cell
// split has 12 faces inside that cell and 4 quarter faces on the plane x = 1/2.
TEST(HexahedralForest, InteriorFacesAndTheBoundaryCoverTheirAreasOnce) {
  const Eigen::AlignedBox3d box(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 0.5, 0.25));
  const HexahedralForest forest = refine_forest(grid_forest(box, Eigen::Vector3i(2, 1, 1), ElementType::hex20), {0});
  const std::vector<ForestFace> faces = forest_interior_faces(forest);
  ASSERT_EQ(faces.size(), 16u);
  double on_interface = 0;
  for (const ForestFace& face : faces)
    if (face.second == forest.leaf_count() - 1 || face.first == forest.leaf_count() - 1) on_interface += face.area;
  EXPECT_NEAR(on_interface, 0.5 * 0.25, 1e-15);

  const ConstrainedHexahedralMesh mesh = forest_mesh(forest);
  const BoundarySurface boundary = forest_boundary_surface(forest, mesh.mesh);
  double area = 0;
  for (Eigen::Index t = 0; t < boundary.surface.triangles.rows(); ++t) {
    const Eigen::Vector3d a = boundary.surface.vertices.row(boundary.surface.triangles(t, 0));
    const Eigen::Vector3d b = boundary.surface.vertices.row(boundary.surface.triangles(t, 1));
    const Eigen::Vector3d c = boundary.surface.vertices.row(boundary.surface.triangles(t, 2));
    area += 0.5 * (b - a).cross(c - a).norm();
  }
  EXPECT_NEAR(area, 2 * (0.5 + 0.25 + 0.125), 1e-14);
}

// A grid over an L-shape: the 2 × 2 × 1 grid without its cell at x, y > 1/2, the cell at
// the re-entrant edge split twice. The boundary holds the faces into the missing cell (the
// re-entrant faces, which lie on no plane of the box) and none of the faces between a leaf
// and its finer neighbours: its area is the L's, and every edge of it is shared by two
// triangles (closed).
TEST(HexahedralForest, TheBoundaryOfAGridWithoutACellHoldsTheFacesIntoIt) {
  HexahedralForest forest = grid_forest(unit_box, Eigen::Vector3i(2, 2, 1), ElementType::hex8);
  keep_leaves(forest, {true, true, true, false});
  ASSERT_EQ(forest.leaf_count(), 3);
  forest = refine_forest(forest, {0});
  forest = refine_forest(forest, {3});  // its eighth at the re-entrant edge (x, y = 1/2)
  const ConstrainedHexahedralMesh mesh = forest_mesh(forest);
  const BoundarySurface boundary = forest_boundary_surface(forest, mesh.mesh);
  double area = 0, re_entrant = 0;
  for (Eigen::Index t = 0; t < boundary.surface.triangles.rows(); ++t) {
    const Eigen::Vector3d a = boundary.surface.vertices.row(boundary.surface.triangles(t, 0));
    const Eigen::Vector3d b = boundary.surface.vertices.row(boundary.surface.triangles(t, 1));
    const Eigen::Vector3d c = boundary.surface.vertices.row(boundary.surface.triangles(t, 2));
    const double triangle = 0.5 * (b - a).cross(c - a).norm();
    area += triangle;
    const Eigen::Vector3d centroid = (a + b + c) / 3;
    const bool on_x_half = std::abs(a.x() - 0.5) + std::abs(b.x() - 0.5) + std::abs(c.x() - 0.5) < 1e-15;
    const bool on_y_half = std::abs(a.y() - 0.5) + std::abs(b.y() - 0.5) + std::abs(c.y() - 0.5) < 1e-15;
    if ((on_x_half && centroid.y() > 0.5) || (on_y_half && centroid.x() > 0.5)) re_entrant += triangle;
  }
  // Top and bottom 3/4 each, the outer sides 1 + 1 + 1/2 + 1/2, the re-entrant ones 1/2 + 1/2.
  EXPECT_NEAR(area, 2 * 0.75 + 3 + 1, 1e-14);
  EXPECT_NEAR(re_entrant, 1, 1e-15);
}

TEST(HexahedralForest, ALeafAtTheDeepestLevelIsRefused) {
  HexahedralForest forest = grid_forest(unit_box, Eigen::Vector3i::Ones(), ElementType::hex8);
  for (int level = 0; level < max_forest_level; ++level) forest = refine_forest(forest, {0});
  EXPECT_EQ(forest.levels[0], max_forest_level);
  EXPECT_THROW(refine_forest(forest, {0}), std::invalid_argument);
}

}  // namespace
}  // namespace altfem
