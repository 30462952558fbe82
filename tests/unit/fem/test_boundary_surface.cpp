// boundary_surface of grids: closed, consistently and outwardly oriented, and
// enclosing the box's volume (divergence theorem).
#include <gtest/gtest.h>

#include <map>
#include <utility>

#include "shared/mesh/boundary_surface.hpp"
#include "shared/mesh/surface_mesh.hpp"
#include "tests/unit/fem/test_meshes.hpp"

namespace altfem {
namespace {

class BoundaryOfGrid : public ::testing::TestWithParam<ElementType> {};

TEST_P(BoundaryOfGrid, ClosedOutwardAndEnclosingTheBox) {
  const ElementType type = GetParam();
  const Eigen::AlignedBox3d box(Eigen::Vector3d(-1.0, 0.0, 0.0), Eigen::Vector3d(1.0, 0.5, 2.0));
  const Eigen::Vector3i n(3, 2, 2);
  const VolumeMesh mesh = test::distorted_grid(box, n, type, 0.15, 3);
  const BoundarySurface boundary = boundary_surface(mesh);
  const SurfaceMesh& surface = boundary.surface;

  // Two triangles per boundary grid face, for tets and (split) hexes alike.
  const int triangles = 4 * (n.x() * n.y() + n.y() * n.z() + n.x() * n.z());
  ASSERT_EQ(surface.triangles.rows(), triangles);
  ASSERT_EQ(static_cast<int>(boundary.cells.size()), triangles);
  ASSERT_EQ(static_cast<Eigen::Index>(boundary.mesh_nodes.size()), surface.vertices.rows());

  // Surface vertices are mesh corner nodes at the same place, all on the box.
  for (Eigen::Index v = 0; v < surface.vertices.rows(); ++v) {
    const int node = boundary.mesh_nodes[v];
    EXPECT_EQ(surface.vertices.row(v), mesh.nodes.row(node));
    EXPECT_TRUE(test::on_box_boundary(surface.vertices.row(v).transpose(), box, 1e-12));
    bool corner = false;
    for (Eigen::Index cell = 0; cell < mesh.cells.rows() && !corner; ++cell)
      for (int c = 0; c < element_corner_count(type); ++c) corner = corner || mesh.cells(cell, c) == node;
    EXPECT_TRUE(corner) << "node " << node;
  }

  // Closed and consistently oriented: every directed edge once, and its reverse once.
  std::map<std::pair<int, int>, int> directed;
  for (Eigen::Index t = 0; t < surface.triangles.rows(); ++t)
    for (int c = 0; c < 3; ++c) ++directed[{surface.triangles(t, c), surface.triangles(t, (c + 1) % 3)}];
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1);
    EXPECT_EQ(directed.count({edge.second, edge.first}), 1u);
  }

  // Outward: the centroid of the cell a triangle bounds lies behind the triangle.
  for (Eigen::Index t = 0; t < surface.triangles.rows(); ++t) {
    const Eigen::Vector3d p0 = surface.vertices.row(surface.triangles(t, 0));
    const Eigen::Vector3d p1 = surface.vertices.row(surface.triangles(t, 1));
    const Eigen::Vector3d p2 = surface.vertices.row(surface.triangles(t, 2));
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    const int corners = element_corner_count(type);
    for (int c = 0; c < corners; ++c) centroid += mesh.nodes.row(mesh.cells(boundary.cells[t], c)).transpose();
    centroid /= corners;
    EXPECT_LT((p1 - p0).cross(p2 - p0).dot(centroid - p0), 0.0) << "triangle " << t;
  }

  EXPECT_NEAR(surface_volume(surface), box.volume(), 1e-13 * box.volume());
}

INSTANTIATE_TEST_SUITE_P(BoundarySurface, BoundaryOfGrid, ::testing::ValuesIn(test::all_element_types),
                         [](const auto& info) { return std::string(element_name(info.param)); });

}  // namespace
}  // namespace altfem
