// A polyhedral mesh cut by a plane (Kaufmann et al. 2009 §9.4): crossed cells split into
// two closed pieces of positive volume, volume conserved, and the two sides share no node
// and no face; blades through nodes, along edges and in faces are ordinary cases. The
// volumes on either side are checked against independent answers: the slab volumes of
// axis planes, and the cube clipped by the plane (clip_tetrahedron) for any plane.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <map>

#include "shared/common/error.hpp"
#include "shared/geometry/clip_convex.hpp"
#include "shared/mesh/convex_cell.hpp"
#include "shared/mesh/cut_polyhedral_mesh.hpp"
#include "tests/unit/mesh/every_cell_closed.hpp"
#include "tests/unit/mesh/seeded_cut_planes.hpp"
#include "tests/unit/mesh/unit_cube_mesh.hpp"

namespace altfem {
namespace {

// The cells whose centroid lies on the positive side of the plane, and their volume.
double volume_on_positive_side(const PolyhedralMesh& mesh, const CuttingPlane& plane) {
  double volume = 0;
  for (int cell = 0; cell < mesh.cell_count(); ++cell)
    if ((mesh.cell_centroids.row(cell).transpose() - plane.point).dot(plane.normal) > 0)
      volume += mesh.cell_volumes[cell];
  return volume;
}

// No node is held by cells on both sides (sides by the centroids of cells well off the plane).
::testing::AssertionResult sides_share_no_node(const PolyhedralMesh& mesh, const CuttingPlane& plane) {
  std::vector<int> side_of_node(mesh.nodes.rows(), 0);
  for (int cell = 0; cell < mesh.cell_count(); ++cell) {
    const int side = (mesh.cell_centroids.row(cell).transpose() - plane.point).dot(plane.normal) > 0 ? 1 : -1;
    for (const int face : mesh.cell_faces[cell])
      for (const int node : mesh.faces[face]) {
        if (side_of_node[node] == -side)
          return ::testing::AssertionFailure() << "node " << node << " is held by cells on both sides";
        side_of_node[node] = side;
      }
  }
  return ::testing::AssertionSuccess();
}

TEST(CutPolyhedralMesh, AnAxisPlaneThroughCellsSplitsThemAndSeparatesTheSides) {
  const PolyhedralMesh mesh = unit_cube_mesh(ElementType::hex8, 2);
  const CuttingPlane plane{Eigen::Vector3d(0.3, 0.0, 0.0), Eigen::Vector3d::UnitX()};
  const PolyhedralCut cut = cut_polyhedral_mesh(mesh, plane);
  EXPECT_EQ(cut.crossed_cells, 4);
  EXPECT_EQ(cut.mesh.cell_count(), 12);
  EXPECT_EQ(cut.separated_faces, 0);
  EXPECT_EQ(cut.duplicated_nodes, 9);  // the blade crosses the 3 × 3 grid edges along x
  EXPECT_TRUE(every_cell_closed(cut.mesh));
  EXPECT_TRUE(sides_share_no_node(cut.mesh, plane));
  EXPECT_NEAR(cut.mesh.cell_volumes.sum(), 1.0, 1e-14);
  EXPECT_NEAR(volume_on_positive_side(cut.mesh, plane), 0.7, 1e-14);
  EXPECT_GT(cut.mesh.cell_volumes.minCoeff(), 0.0);
  for (int cell = 0; cell < cut.mesh.cell_count(); ++cell) {
    const int parent = cut.parent_cell[cell];
    EXPECT_TRUE(mesh.cell_centroids(parent, 0) < 0.5 || cut.mesh.cell_kinds[cell] != PolyhedralCellKind::split) << cell;
  }
}

TEST(CutPolyhedralMesh, APlaneThroughGridNodesSeparatesAlongFaces) {
  const PolyhedralMesh mesh = unit_cube_mesh(ElementType::hex8, 2);
  const CuttingPlane plane{Eigen::Vector3d(0.5, 0.5, 0.5), Eigen::Vector3d(0.0, 0.0, -2.0)};
  const PolyhedralCut cut = cut_polyhedral_mesh(mesh, plane);
  EXPECT_EQ(cut.crossed_cells, 0);
  EXPECT_EQ(cut.mesh.cell_count(), 8);
  EXPECT_EQ(cut.separated_faces, 4);
  EXPECT_EQ(cut.duplicated_nodes, 9);
  EXPECT_EQ(cut.mesh.face_count(), mesh.face_count() + 4);
  EXPECT_TRUE(every_cell_closed(cut.mesh));
  EXPECT_TRUE(sides_share_no_node(cut.mesh, plane));
  EXPECT_EQ(cut.mesh.cell_volumes, mesh.cell_volumes);  // untouched cells, bit for bit
}

TEST(CutPolyhedralMesh, APlaneAlongEdgesAndDiagonalsOfTetrahedra) {
  const PolyhedralMesh mesh = unit_cube_mesh(ElementType::tet4, 2);
  for (const Eigen::Vector3d& normal :
       {Eigen::Vector3d(1, -1, 0), Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(0, 1, -1)}) {
    const CuttingPlane plane{Eigen::Vector3d(0.5, 0.5, 0.5), normal};
    const PolyhedralCut cut = cut_polyhedral_mesh(mesh, plane);
    EXPECT_TRUE(every_cell_closed(cut.mesh)) << normal.transpose();
    EXPECT_TRUE(sides_share_no_node(cut.mesh, plane)) << normal.transpose();
    EXPECT_GT(cut.mesh.cell_volumes.minCoeff(), 0.0);
    EXPECT_NEAR(cut.mesh.cell_volumes.sum(), 1.0, 1e-14);
    EXPECT_NEAR(volume_on_positive_side(cut.mesh, plane), 0.5, 1e-14) << normal.transpose();  // the cube's centre
  }
}

// The unit cube's volume on the positive side of a plane, by clipping its six Kuhn
// tetrahedra (an independent construction).
double clipped_cube_volume(const CuttingPlane& plane) {
  const PolyhedralMesh tetrahedra = unit_cube_mesh(ElementType::tet4, 1);
  // The kept side of a ClipPlane is behind (b − a) × (c − a): point it against the normal.
  Eigen::Index smallest = 0;
  plane.normal.cwiseAbs().minCoeff(&smallest);
  const Eigen::Vector3d first = plane.normal.cross(Eigen::Vector3d::Unit(smallest));
  const ClipPlane clip{plane.point, plane.point + plane.normal.cross(first), plane.point + first};
  double volume = 0;
  for (int cell = 0; cell < tetrahedra.cell_count(); ++cell) {
    const std::vector<int> corners = cell_node_set(tetrahedra, cell);
    TetrahedronCorners tetrahedron;
    for (int k = 0; k < 4; ++k) tetrahedron.row(k) = tetrahedra.nodes.row(corners[k]);
    for (const TetrahedronCorners& piece : clip_tetrahedron(tetrahedron, {clip}))
      volume +=
          std::abs((piece.row(1) - piece.row(0)).cross(piece.row(2) - piece.row(0)).dot(piece.row(3) - piece.row(0))) /
          6;
  }
  return volume;
}

// Seeded planes of every degenerate kind (seeded_cut_planes.hpp): 200 per mesh.
TEST(CutPolyhedralMesh, SeededPlanesGiveClosedPiecesOfPositiveVolumeOnEveryKindOfMesh) {
  for (const ElementType type : {ElementType::tet4, ElementType::hex8}) {
    const PolyhedralMesh mesh = unit_cube_mesh(type, 3);
    for (const CuttingPlane& plane : seeded_cut_planes(mesh.nodes, 200)) {
      SCOPED_TRACE(::testing::Message() << "point " << plane.point.transpose() << ", normal "
                                        << plane.normal.transpose());
      PolyhedralCut cut;
      ASSERT_NO_THROW(cut = cut_polyhedral_mesh(mesh, plane));
      ASSERT_TRUE(every_cell_closed(cut.mesh));
      ASSERT_GT(cut.mesh.cell_volumes.minCoeff(), 0.0);
      EXPECT_NEAR(cut.mesh.cell_volumes.sum(), 1.0, 1e-13);
      ASSERT_TRUE(every_node_at_its_source(mesh.nodes, cut));
      EXPECT_NEAR(volume_on_positive_side(cut.mesh, plane), clipped_cube_volume(plane), 1e-9);
    }
  }
}

TEST(CutPolyhedralMesh, APlaneThatMissesTheMeshChangesNothing) {
  const PolyhedralMesh mesh = unit_cube_mesh(ElementType::tet4, 2);
  const PolyhedralCut cut = cut_polyhedral_mesh(mesh, {Eigen::Vector3d(0, 0, 2), Eigen::Vector3d::UnitZ()});
  EXPECT_EQ(cut.crossed_cells, 0);
  EXPECT_EQ(cut.duplicated_nodes, 0);
  EXPECT_EQ(cut.mesh.faces, mesh.faces);
  EXPECT_EQ(cut.mesh.nodes, mesh.nodes);
  EXPECT_THROW(cut_polyhedral_mesh(mesh, {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()}), std::invalid_argument);
}

}  // namespace
}  // namespace altfem
