// A surface blade's triangle leaves each cell it reaches whole or in one piece a side of
// its plane (issue #33; join_cut_pieces.hpp, join_pieces_by_side): its edges' splits only
// bound the faces its separation may open, so the pieces they make are joined again, and
// a cell stays convex for fcm's and fem's cones. One triangle in the plane z = 0.5 of the
// unit cube: covering part of the section, two convex halves joined where it does not
// reach; covering all of it, two halves apart; its box meeting the cube but its plane's
// part over the section not in it, the cube whole.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <vector>

#include "shared/mesh/convex_cell.hpp"
#include "shared/mesh/cut_by_surface.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "tests/unit/mesh/every_cell_closed.hpp"

namespace altfem {
namespace {

PolyhedralMesh unit_cube() {
  const Eigen::AlignedBox3d box(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  return polyhedral_mesh_from_volume_mesh(structured_grid(box, Eigen::Vector3i::Ones(), ElementType::hex8));
}

// The triangle with corners (x, y) at z = 0.5.
SurfaceBlade triangle_at_half_height(const std::array<Eigen::Vector2d, 3>& corners) {
  SurfaceBlade blade;
  blade.vertices.resize(3, 3);
  for (int k = 0; k < 3; ++k) blade.vertices.row(k) << corners[k].x(), corners[k].y(), 0.5;
  blade.triangles.resize(1, 3);
  blade.triangles << 0, 1, 2;
  return blade;
}

struct CutCube {
  PolyhedralMesh mesh;
  int interior_faces = 0;
};

CutCube cut_cube_by(const SurfaceBlade& blade) {
  CutCube result{cut_by_surface_steps(unit_cube(), blade).mesh};
  compute_polyhedral_geometry(result.mesh);
  for (int face = 0; face < result.mesh.face_count(); ++face)
    result.interior_faces += result.mesh.face_cells(face, 1) >= 0;
  return result;
}

void expect_convex_halves(const PolyhedralMesh& mesh) {
  ASSERT_EQ(mesh.cell_count(), 2);
  EXPECT_TRUE(every_cell_closed(mesh));
  for (int cell = 0; cell < 2; ++cell) {
    EXPECT_NEAR(mesh.cell_volumes(cell), 0.5, 1e-15) << cell;
    EXPECT_TRUE(is_convex_cell(mesh, cell, cell_node_set(mesh, cell))) << cell;
  }
}

TEST(JoinPiecesBySide, ATriangleOverPartOfTheSectionLeavesTwoConvexHalvesJoinedBeyondIt) {
  // Its hypotenuse x + y = 0.6 crosses the section: the halves open over x + y < 0.6 only.
  const CutCube cut = cut_cube_by(triangle_at_half_height({{{-1, -1}, {1.6, -1}, {-1, 1.6}}}));
  expect_convex_halves(cut.mesh);
  EXPECT_GT(cut.interior_faces, 0);
  double open_area = 0;
  for (int face = 0; face < cut.mesh.face_count(); ++face)
    if (cut.mesh.face_cells(face, 1) < 0 && std::abs(cut.mesh.face_centroids(face, 2) - 0.5) < 1e-15)
      open_area += cut.mesh.face_areas(face);
  EXPECT_NEAR(open_area, 2 * (0.6 * 0.6 / 2), 1e-15);  // the triangle x + y < 0.6, each side
}

TEST(JoinPiecesBySide, ATriangleOverTheWholeSectionLeavesTwoHalvesApart) {
  const CutCube cut = cut_cube_by(triangle_at_half_height({{{-1, -1}, {4, -1}, {-1, 4}}}));
  expect_convex_halves(cut.mesh);
  EXPECT_EQ(cut.interior_faces, 0);
}

TEST(JoinPiecesBySide, ATriangleWhoseBoxMeetsTheCubeButNotItsSectionLeavesItWhole) {
  // Its box [0.9, 2]² meets the section's corner; its hypotenuse x + y = 2.9 passes beyond it.
  const CutCube cut = cut_cube_by(triangle_at_half_height({{{0.9, 2}, {2, 0.9}, {2, 2}}}));
  ASSERT_EQ(cut.mesh.cell_count(), 1);
  EXPECT_TRUE(every_cell_closed(cut.mesh));
  EXPECT_NEAR(cut.mesh.cell_volumes(0), 1, 1e-15);
  EXPECT_EQ(cut.mesh.face_count(), 6);  // its split's faces merged again, its nodes dropped
}

}  // namespace
}  // namespace altfem
