// Finite blades (issue #33): a convex polygon separates only the sections it covers. A
// polygon covering the whole section cuts as its plane; a notch along faces opens only
// the faces it covers and leaves the nodes at its tip joined; a blade ending inside cells
// splits them into pieces that stay joined; seeded polygons of every degenerate kind give
// closed pieces of positive volume, conforming tetrahedra, and the volume unchanged.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <set>

#include "shared/mesh/cut_polyhedral_mesh.hpp"
#include "shared/mesh/cut_tetrahedral_mesh.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "tests/unit/mesh/every_cell_closed.hpp"
#include "tests/unit/mesh/seeded_cut_planes.hpp"

namespace altfem {
namespace {

VolumeMesh unit_cube_grid(ElementType type, int cells_per_axis) {
  const Eigen::AlignedBox3d box(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  return structured_grid(box, Eigen::Vector3i::Constant(cells_per_axis), type);
}

// The rectangle of the plane x = `x` over y ∈ [−1, 2] and z ∈ [z_low, 2].
CuttingPlane notch(double x, double z_low) {
  return polygon_blade({Eigen::Vector3d(x, -1, z_low), Eigen::Vector3d(x, 2, z_low), Eigen::Vector3d(x, 2, 2),
                        Eigen::Vector3d(x, -1, 2)});
}

// The nodes held by cells on both sides of x = `x`, by their centroids.
std::set<int> nodes_held_across(const PolyhedralMesh& mesh, double x) {
  std::vector<int> side_of_node(mesh.nodes.rows(), 0);
  std::set<int> across;
  for (int cell = 0; cell < mesh.cell_count(); ++cell) {
    const int side = mesh.cell_centroids(cell, 0) > x ? 1 : -1;
    for (const int face : mesh.cell_faces[cell])
      for (const int node : mesh.faces[face]) {
        if (side_of_node[node] == -side) across.insert(node);
        side_of_node[node] = side;
      }
  }
  return across;
}

TEST(CutByPolygon, APolygonCoveringTheWholeSectionCutsAsItsPlane) {
  const PolyhedralMesh mesh = polyhedral_mesh_from_volume_mesh(unit_cube_grid(ElementType::tet4, 3));
  const CuttingPlane plane{Eigen::Vector3d(0.4, 0.2, 0.3), Eigen::Vector3d(1, 0.3, -0.2)};
  CuttingPlane polygon = plane;
  const Eigen::Vector3d first = plane.normal.cross(Eigen::Vector3d::UnitZ()), second = plane.normal.cross(first);
  polygon.polygon = {plane.point - 9 * first - 9 * second, plane.point + 9 * first - 9 * second,
                     plane.point + 9 * first + 9 * second, plane.point - 9 * first + 9 * second};
  const PolyhedralCut by_plane = cut_polyhedral_mesh(mesh, plane), by_polygon = cut_polyhedral_mesh(mesh, polygon);
  EXPECT_EQ(by_polygon.joined_cells, 0);
  EXPECT_EQ(by_polygon.crossed_cells, by_plane.crossed_cells);
  EXPECT_EQ(by_polygon.duplicated_nodes, by_plane.duplicated_nodes);
  EXPECT_EQ(by_polygon.mesh.faces, by_plane.mesh.faces);
  EXPECT_EQ(by_polygon.mesh.nodes, by_plane.mesh.nodes);
}

// A 4³ grid notched from the top half-way down along the grid plane x = 0.5: the 8 faces
// it covers open, the 5 × 3 nodes on them less the 5 at its tip (z = 0.5, joined through
// the faces below) are copied.
TEST(CutByPolygon, ANotchAlongFacesOpensTheFacesItCoversAndNotItsTip) {
  const PolyhedralMesh mesh = polyhedral_mesh_from_volume_mesh(unit_cube_grid(ElementType::hex8, 4));
  const PolyhedralCut cut = cut_polyhedral_mesh(mesh, notch(0.5, 0.5));
  EXPECT_EQ(cut.crossed_cells, 0);
  EXPECT_EQ(cut.separated_faces, 8);
  EXPECT_EQ(cut.duplicated_nodes, 10);
  EXPECT_TRUE(every_cell_closed(cut.mesh));
  EXPECT_EQ(cut.mesh.cell_volumes, mesh.cell_volumes);
  const std::set<int> across = nodes_held_across(cut.mesh, 0.5);
  EXPECT_EQ(across.size(), 5u * 3u);  // the tip's 5 and the 10 below it
  for (const int node : across) EXPECT_LE(cut.mesh.nodes(node, 2), 0.5) << node;
}

// The plane x = 0.4 crosses the 16 cells of the column x ∈ [0.25, 0.5]; a blade over z ≥
// 0.6 covers the sections of the top layer's 4 only: those separate (their 5 crossing
// nodes at z = 1 copied, those at z = 0.75 joined through the pieces below), the other 12
// are split into pieces that stay joined.
TEST(CutByPolygon, ABladeEndingInsideCellsKeepsTheirPiecesJoined) {
  const PolyhedralMesh mesh = polyhedral_mesh_from_volume_mesh(unit_cube_grid(ElementType::hex8, 4));
  const PolyhedralCut cut = cut_polyhedral_mesh(mesh, notch(0.4, 0.6));
  EXPECT_EQ(cut.crossed_cells, 16);
  EXPECT_EQ(cut.joined_cells, 12);
  EXPECT_EQ(cut.duplicated_nodes, 5);
  EXPECT_EQ(cut.mesh.cell_count(), 64 + 16);
  EXPECT_TRUE(every_cell_closed(cut.mesh));
  EXPECT_GT(cut.mesh.cell_volumes.minCoeff(), 0.0);
  EXPECT_NEAR(cut.mesh.cell_volumes.sum(), 1.0, 1e-14);
  for (const int node : nodes_held_across(cut.mesh, 0.4)) EXPECT_LE(cut.mesh.nodes(node, 2), 0.75) << node;
}

// A square swept along its side is the longer rectangle; a triangle swept along its
// hypotenuse's normal is a pentagon (the translate's right-angle corner falls inside).
TEST(CutByPolygon, ASweptPolygonIsTheHullOfItAndItsTranslate) {
  const auto corners_of = [](const CuttingPlane& blade) {
    std::set<std::array<double, 3>> corners;
    for (const Eigen::Vector3d& corner : blade.polygon) corners.insert({corner.x(), corner.y(), corner.z()});
    return corners;
  };
  const CuttingPlane square = polygon_blade(
      {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(1, 1, 0), Eigen::Vector3d(0, 1, 0)});
  const CuttingPlane rectangle = swept_blade(square, Eigen::Vector3d(0.5, 0, 0));
  EXPECT_EQ(corners_of(rectangle), (std::set<std::array<double, 3>>{{0, 0, 0}, {1.5, 0, 0}, {1.5, 1, 0}, {0, 1, 0}}));
  EXPECT_EQ(blade_polygon_problem(rectangle), "");
  const CuttingPlane triangle =
      polygon_blade({Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)});
  const CuttingPlane pentagon = swept_blade(triangle, Eigen::Vector3d(1, 1, 0));
  EXPECT_EQ(corners_of(pentagon),
            (std::set<std::array<double, 3>>{{0, 0, 0}, {1, 0, 0}, {2, 1, 0}, {1, 2, 0}, {0, 1, 0}}));
  EXPECT_EQ(blade_polygon_problem(pentagon), "");
  EXPECT_EQ(swept_blade(square, Eigen::Vector3d::Zero()).polygon.size(), 4u);
}

// A 4³ grid cut in two at x = 0.5, then along the grid plane y = 0.5 with piece_at in
// the half x < 0.5: only that half's 2 × 4 faces in the plane open (16 without it).
TEST(CutByPolygon, PieceAtCutsOnlyThePieceHoldingIt) {
  const PolyhedralMesh mesh = polyhedral_mesh_from_volume_mesh(unit_cube_grid(ElementType::hex8, 4));
  const PolyhedralMesh halves = cut_polyhedral_mesh(mesh, {Eigen::Vector3d(0.5, 0, 0), Eigen::Vector3d::UnitX()}).mesh;
  CuttingPlane blade{Eigen::Vector3d(0, 0.5, 0), Eigen::Vector3d::UnitY()};
  EXPECT_EQ(cut_polyhedral_mesh(halves, blade).separated_faces, 16);
  blade.piece_at = Eigen::Vector3d(0.1, 0.1, 0.1);
  const PolyhedralCut cut = cut_polyhedral_mesh(halves, blade);
  EXPECT_EQ(cut.separated_faces, 8);
  EXPECT_EQ(cut.duplicated_nodes, 3 * 5);  // the nodes of x ∈ {0, 0.25, 0.5} on the plane
  EXPECT_TRUE(every_cell_closed(cut.mesh));
  // Through cells: the plane y = 0.6 splits only the 8 cells of that half it crosses.
  blade.point = Eigen::Vector3d(0, 0.6, 0);
  EXPECT_EQ(cut_polyhedral_mesh(halves, blade).crossed_cells, 8);
}

TEST(CutByPolygon, RefusesPolygonsThatCannotBeBlades) {
  const PolyhedralMesh mesh = polyhedral_mesh_from_volume_mesh(unit_cube_grid(ElementType::hex8, 1));
  const Eigen::Vector3d a(0.5, 0, 0), b(0.5, 1, 0), c(0.5, 1, 1), d(0.5, 0, 1);
  for (const std::vector<Eigen::Vector3d>& corners : {std::vector<Eigen::Vector3d>{a, b},
                                                      {a, b, Eigen::Vector3d(0.5, 2, 0)},
                                                      {a, c, b, d},
                                                      {a, b, c, Eigen::Vector3d(0.6, 0, 1)},
                                                      {a, b, b, c}}) {
    EXPECT_FALSE(blade_polygon_problem(polygon_blade(corners)).empty());
    EXPECT_THROW(cut_polyhedral_mesh(mesh, polygon_blade(corners)), std::invalid_argument);
  }
  EXPECT_EQ(blade_polygon_problem(polygon_blade({a, b, c, d})), "");
}

// Seeded blades of every degenerate kind (seeded_cut_polygons): closed pieces of positive
// volume, the volume unchanged, nodes where their sources put them; the Kuhn tetrahedra
// cut by them stay conforming (a face of one tetrahedron only lies on the cube's boundary
// or on the blade's plane).
TEST(CutByPolygon, SeededPolygonsGiveClosedPiecesAndConformingTetrahedra) {
  for (const ElementType type : {ElementType::tet4, ElementType::hex8}) {
    const VolumeMesh grid = unit_cube_grid(type, 3);
    const PolyhedralMesh mesh = polyhedral_mesh_from_volume_mesh(grid);
    for (const CuttingPlane& blade : seeded_cut_polygons(mesh.nodes, 1.0 / 3.0, 200)) {
      SCOPED_TRACE(::testing::Message() << "point " << blade.point.transpose() << ", normal "
                                        << blade.normal.transpose() << ", " << blade.polygon.size() << " corners");
      PolyhedralCut cut;
      ASSERT_NO_THROW(cut = cut_polyhedral_mesh(mesh, blade));
      ASSERT_TRUE(every_cell_closed(cut.mesh));
      ASSERT_GT(cut.mesh.cell_volumes.minCoeff(), 0.0);
      EXPECT_NEAR(cut.mesh.cell_volumes.sum(), 1.0, 1e-13);
      ASSERT_TRUE(every_node_at_its_source(mesh.nodes, cut));
      if (type != ElementType::tet4) continue;
      TetrahedralCut tetrahedra;
      ASSERT_NO_THROW(tetrahedra = cut_tetrahedral_mesh({grid}, blade));
      double volume = 0;
      std::map<std::array<int, 3>, int> face_count;
      for (Eigen::Index cell = 0; cell < tetrahedra.result.mesh.cells.rows(); ++cell) {
        const auto row = tetrahedra.result.mesh.cells.row(cell);
        const Eigen::Vector3d origin = tetrahedra.result.mesh.nodes.row(row(0));
        const double cell_volume = (Eigen::Vector3d(tetrahedra.result.mesh.nodes.row(row(1))) - origin)
                                       .cross(Eigen::Vector3d(tetrahedra.result.mesh.nodes.row(row(2))) - origin)
                                       .dot(Eigen::Vector3d(tetrahedra.result.mesh.nodes.row(row(3))) - origin) /
                                   6;
        ASSERT_GT(cell_volume, 0.0) << "tetrahedron " << cell;
        volume += cell_volume;
        for (const auto& face : std::array<std::array<int, 3>, 4>{{{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}}}) {
          std::array<int, 3> key{row(face[0]), row(face[1]), row(face[2])};
          std::sort(key.begin(), key.end());
          ++face_count[key];
        }
      }
      EXPECT_NEAR(volume, 1.0, 1e-12);
      if (tetrahedra.flat_tetrahedra > 0) continue;  // slivers left out leave faces unmatched
      for (const auto& [face, count] : face_count) {
        ASSERT_LE(count, 2);
        if (count == 2) continue;
        const auto on = [&](auto&& predicate) {
          return std::all_of(face.begin(), face.end(), [&](int node) {
            return predicate(Eigen::Vector3d(tetrahedra.result.mesh.nodes.row(node)));
          });
        };
        const bool on_boundary = [&] {
          for (int axis = 0; axis < 3; ++axis)
            for (const double wall : {0.0, 1.0})
              if (on([&](const Eigen::Vector3d& x) { return x[axis] == wall; })) return true;
          return false;
        }();
        const bool on_blade = on([&](const Eigen::Vector3d& x) {
          return std::abs((x - blade.point).dot(blade.normal.normalized())) <= 1e-12;
        });
        ASSERT_TRUE(on_boundary || on_blade) << "an unmatched face inside: not conforming";
      }
    }
  }
}

}  // namespace
}  // namespace altfem
