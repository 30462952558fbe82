// Tetrahedral meshes that keep apart what the geometry keeps apart (#21 item 5):
// exact meshes of box-built shapes, protected sharp edges, and the checks of
// tetrahedralize_geometry with the key they name.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "shared/common/error.hpp"
#include "shared/mesh/convex_cell.hpp"
#include "shared/mesh/mesh_components.hpp"
#include "shared/mesh/slice_into_polyhedra.hpp"
#include "shared/mesh/snap_to_planar_faces.hpp"
#include "shared/mesh/tetrahedralize.hpp"
#include "shared/scene/tetrahedralize_geometry.hpp"

namespace altfem {
namespace {

double mesh_volume(const VolumeMesh& mesh) {
  double volume = 0;
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell) {
    const Eigen::Vector3d a = mesh.nodes.row(mesh.cells(cell, 0)), b = mesh.nodes.row(mesh.cells(cell, 1)),
                          c = mesh.nodes.row(mesh.cells(cell, 2)), d = mesh.nodes.row(mesh.cells(cell, 3));
    const double signed_volume = (b - a).cross(c - a).dot(d - a) / 6.0;
    EXPECT_GT(signed_volume, 0.0) << "cell " << cell;
    volume += signed_volume;
  }
  return volume;
}

double polyline_length(const Polyline& line) {
  double length = 0;
  for (std::size_t i = 1; i < line.size(); ++i) length += (line[i] - line[i - 1]).norm();
  return length;
}

double total_length(const std::vector<Polyline>& lines) {
  double length = 0;
  for (const Polyline& line : lines) length += polyline_length(line);
  return length;
}

// The shape of the issue: two boxes 4 mm apart.
ShapePointer two_boxes() {
  return make_union({make_box({0, 0, 0}, {1, 0.1, 0.1}), make_box({0.3, 0.104, 0}, {1, 0.204, 0.1})});
}

SceneGeometry shape_geometry(ShapePointer shape) {
  SceneGeometry geometry;
  geometry.scene_file = "scene.json";
  geometry.shape = std::move(shape);
  geometry.bounds = geometry.shape->bounding_box();
  geometry.volume = geometry.shape->volume();
  return geometry;
}

TEST(TetrahedralizeBoxShape, KeepsTwoBoxesFourMillimetresApartApart) {
  const VolumeMesh mesh = tetrahedralize_box_shape(*two_boxes(), 0.07);
  EXPECT_EQ(volume_mesh_components(mesh), 2);
  EXPECT_NEAR(mesh_volume(mesh), 0.1 * 0.1 + 0.7 * 0.1 * 0.1, 1e-14);
  // No node in the gap.
  for (Eigen::Index node = 0; node < mesh.nodes.rows(); ++node) {
    const double y = mesh.nodes(node, 1);
    EXPECT_FALSE(y > 0.1 + 1e-12 && y < 0.104 - 1e-12) << node;
  }
}

TEST(TetrahedralizeBoxShape, MeshesAnLShapeAndANotchExactly) {
  const ShapePointer l_shape = make_union({make_box({0, 0, 0}, {1, 0.2, 0.2}), make_box({0, 0, 0}, {0.2, 1, 0.2})});
  const VolumeMesh l_mesh = tetrahedralize_box_shape(*l_shape, 0.1);
  EXPECT_EQ(volume_mesh_components(l_mesh), 1);
  EXPECT_NEAR(mesh_volume(l_mesh), 2 * 0.04 - 0.2 * 0.04, 1e-14);
  const ShapePointer notched =
      make_difference({make_box({0, 0, 0}, {1, 1, 1}), make_box({0.3, 0.3, 0.5}, {0.6, 2, 2})});
  EXPECT_NEAR(mesh_volume(tetrahedralize_box_shape(*notched, 0.25)), 1 - 0.3 * 0.7 * 0.5, 1e-14);
  EXPECT_FALSE(make_sphere({0, 0, 0}, 1)->axis_planes());
}

TEST(SharpEdges, BoxEdgesCylinderRimsAndTheirPartsOnACsgSurface) {
  EXPECT_NEAR(total_length(make_box({0, 0, 0}, {1, 2, 3})->sharp_edges(0.1)), 4 * 6.0, 1e-12);
  EXPECT_EQ(make_box({0, 0, 0}, {1, 2, 3})->sharp_edges(0.1).size(), 12u);
  const auto tube = make_cylinder({0, 0, 0}, {0, 0, 1}, 2.0, 0.5, 0.3);
  const auto rims = tube->sharp_edges(0.01);
  ASSERT_EQ(rims.size(), 4u);
  // Inscribed polygons: the length is 2π r up to O(spacing²).
  EXPECT_NEAR(total_length(rims), 2 * 2 * std::numbers::pi * (0.5 + 0.3), 1e-3);
  EXPECT_NEAR(tube->smallest_feature(), 0.2, 1e-15);
  const auto overlap = make_union({make_box({0, 0, 0}, {1, 1, 1}), make_box({0.5, 0.2, 0.2}, {1.5, 0.8, 0.8})});
  // Box 2 (1 × 0.6 × 0.6) pokes out of the unit cube's face x = 1: its 4 edges along x
  // keep their 0.5 outside, the 4 edges of its far face x = 1.5 stay (0.6 each), those
  // of its near face x = 0.5 are buried. The cube keeps all 12 edges (box 2 touches none).
  // The two meet along a 0.6 square on x = 1, found once (marching squares cut its
  // corners by less than the spacing).
  const double overlap_length = total_length(overlap->sharp_edges(0.05));
  EXPECT_LE(overlap_length, 12 + 4 * 0.5 + 4 * 0.6 + 4 * 0.6 + 1e-7);
  EXPECT_GE(overlap_length, 12 + 4 * 0.5 + 4 * 0.6 + 4 * 0.6 - 4 * 0.05);
  EXPECT_NEAR(overlap->smallest_feature(), 0.6, 1e-15);
}

TEST(SharpEdges, AHalfBallsRimIsWhereTheBoxFaceMeetsTheSphere) {
  const double radius = 0.5;
  const auto half_ball = make_intersection({make_sphere({0, 0, 0}, radius), make_box({-1, -1, 0}, {1, 1, 1})});
  const auto rims = half_ball->sharp_edges(0.02);
  ASSERT_EQ(rims.size(), 1u);
  EXPECT_EQ(rims[0].front(), rims[0].back());  // closed
  EXPECT_NEAR(polyline_length(rims[0]), 2 * std::numbers::pi * radius, 2e-3);
  for (const Eigen::Vector3d& x : rims[0]) {
    EXPECT_NEAR(x.z(), 0.0, 1e-12);
    EXPECT_NEAR(x.norm(), radius, 1e-9);
  }
  // A bar whose end pokes through a ball: the box's edges end on the sphere where the
  // curves on its faces begin, at exactly the same points.
  const auto bar_and_ball = make_union({make_box({0, 0, 0}, {0.6, 0.2, 0.2}), make_sphere({0.55, 0.1, 0.1}, 0.2)});
  const auto edges = bar_and_ball->sharp_edges(0.01);
  int shared_ends = 0;
  for (std::size_t a = 0; a < edges.size(); ++a)
    for (std::size_t b = a + 1; b < edges.size(); ++b)
      for (const auto* x : {&edges[a].front(), &edges[a].back()})
        for (const auto* y : {&edges[b].front(), &edges[b].back()}) {
          const double distance = (*x - *y).norm();
          EXPECT_TRUE(distance == 0 || distance > 1e-4) << distance;
          shared_ends += distance == 0;
        }
  EXPECT_GE(shared_ends, 4);
}

TEST(TetrahedralizeShape, ProtectsAHalfBallsRim) {
  const double radius = 0.5, size = 0.15;
  const auto half_ball = make_intersection({make_sphere({0, 0, 0}, radius), make_box({-1, -1, 0}, {1, 1, 1})});
  const VolumeMesh mesh = tetrahedralize_shape(*half_ball, size);
  int rim_nodes = 0;
  for (Eigen::Index node = 0; node < mesh.nodes.rows(); ++node) {
    const Eigen::Vector3d x = mesh.nodes.row(node);
    if (std::abs(x.z()) < 1e-9 && std::abs(x.norm() - radius) < 1e-3) ++rim_nodes;
  }
  EXPECT_GE(rim_nodes, static_cast<int>(2 * std::numbers::pi * radius / size));
}

// Mesh_3 leaves a flat face's vertices on the level set to its error bound (the half-ball's
// at |z| up to 1e-7); snapped, every boundary vertex near z = 0 is on it exactly, and every
// tetrahedron keeps a positive volume.
TEST(TetrahedralizeShape, AHalfBallsFlatFaceIsFlat) {
  const auto half_ball = make_intersection({make_sphere({0, 0, 0}, 1), make_box({-2, -2, 0}, {2, 2, 2})});
  const VolumeMesh mesh = tetrahedralize_shape(*half_ball, 0.2);
  int on_face = 0;
  for (Eigen::Index node = 0; node < mesh.nodes.rows(); ++node) {
    const double z = mesh.nodes(node, 2);
    if (std::abs(z) < 1e-4) {
      EXPECT_EQ(z, 0.0) << "node " << node;
      ++on_face;
    }
  }
  EXPECT_GT(on_face, 20);
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell) {
    const Eigen::Vector3d a = mesh.nodes.row(mesh.cells(cell, 0));
    const double volume = (Eigen::Vector3d(mesh.nodes.row(mesh.cells(cell, 1))) - a)
                              .cross(Eigen::Vector3d(mesh.nodes.row(mesh.cells(cell, 2))) - a)
                              .dot(Eigen::Vector3d(mesh.nodes.row(mesh.cells(cell, 3))) - a);
    EXPECT_GT(volume, 0.0) << "cell " << cell;
  }
}

// What the flat face is for: the half-ball sliced by a grid whose bottom layer it cuts into
// slabs (Kaufmann et al. 2009 §9.2). Bent by 1e-7, those slabs were not convex, and a
// refinement, which splits convex cells only, left them whole however large their error.
TEST(TetrahedralizeShape, TheSlicedHalfBallsCellsAtItsFlatFaceAreConvex) {
  const auto half_ball = make_intersection({make_sphere({0, 0, 0}, 1), make_box({-2, -2, 0}, {2, 2, 2})});
  SlicingOptions options;
  options.resolution = 4;
  const PolyhedralMesh mesh = slice_into_polyhedra(*half_ball, options).mesh;
  int at_face = 0;
  for (int cell = 0; cell < mesh.cell_count(); ++cell) {
    const std::vector<int> nodes = cell_node_set(mesh, cell);
    bool touches = false;
    for (const int node : nodes) touches = touches || mesh.nodes(node, 2) == 0.0;
    if (!touches) continue;
    ++at_face;
    EXPECT_TRUE(is_convex_cell(mesh, cell, nodes)) << "cell " << cell;
  }
  EXPECT_GE(at_face, 12);
}

// A node off a planar face by less than the tolerance lands on it, one farther stays, and a
// node whose move would invert a tetrahedron stays.
TEST(SnapToPlanarFaces, MovesOnlyBoundaryNodesWithinTheTolerance) {
  VolumeMesh mesh;
  mesh.element_type = ElementType::tet4;
  mesh.nodes.resize(5, 3);
  mesh.nodes << 0, 0, 3e-8, 1, 0, 0, 0, 1, 1e-3, 0, 0, 1, 0.2, 0.2, 1e-7;
  mesh.cells.resize(1, 4);
  mesh.cells << 0, 1, 2, 3;
  const PlanarFace bottom{Eigen::Vector3d(-1, -1, 0), Eigen::Vector3d(3, 0, 0), Eigen::Vector3d(0, 3, 0)};
  EXPECT_EQ(snap_to_planar_faces(mesh, {bottom}, 1e-6), 1);
  EXPECT_EQ(mesh.nodes(0, 2), 0.0);
  EXPECT_EQ(mesh.nodes(2, 2), 1e-3);
  EXPECT_EQ(mesh.nodes(4, 2), 1e-7);  // in no cell: not on the boundary
  // A flat tetrahedron whose apex is within the tolerance: snapping it would invert it.
  VolumeMesh flat = mesh;
  flat.nodes.row(3) << 0.3, 0.3, 5e-7;
  flat.nodes.row(0) << 0, 0, 0;
  flat.nodes.row(2) << 0, 1, 0;
  EXPECT_EQ(snap_to_planar_faces(flat, {bottom}, 1e-6), 0);
  EXPECT_EQ(flat.nodes(3, 2), 5e-7);
}

TEST(TetrahedralizeShape, ProtectsACylindersRims) {
  const double radius = 0.5, height = 1.0, size = 0.2;
  const auto cylinder = make_cylinder({0, 0, 0}, {0, 0, 1}, height, radius);
  const VolumeMesh mesh = tetrahedralize_shape(*cylinder, size);
  // Nodes on the bottom rim (the protected polyline's chords, spacing size / 4, sag
  // below 1e-3), spread all around it.
  int rim_nodes = 0;
  for (Eigen::Index node = 0; node < mesh.nodes.rows(); ++node) {
    const Eigen::Vector3d x = mesh.nodes.row(node);
    if (std::abs(x.z()) < 1e-9 && std::abs(x.head<2>().norm() - radius) < 1e-3) ++rim_nodes;
  }
  EXPECT_GE(rim_nodes, static_cast<int>(2 * std::numbers::pi * radius / size));
  const double exact = std::numbers::pi * radius * radius * height;
  // Facets are chords of the curved side (sag h² / 8R), so the volume falls short by O(h²).
  EXPECT_LT(std::abs(mesh_volume(mesh) - exact) / exact, 0.03);
}

TEST(TetrahedralizeGeometry, BoxShapesAreExactAndPassTheChecks) {
  const VolumeMesh mesh =
      tetrahedralize_geometry(shape_geometry(two_boxes()), 0.07, "/discretization/fem/max_cell_size");
  EXPECT_EQ(volume_mesh_components(mesh), 2);
}

TEST(TetrahedralizeGeometry, ACoarseMeshThatGluesTwoBallsExitsNamingTheSizeKey) {
  // Two balls 0.02 apart, meshed with cells of 0.3: Mesh_3 bridges the gap.
  const auto balls = make_union({make_sphere({0, 0, 0}, 0.5), make_sphere({1.02, 0, 0}, 0.5)});
  try {
    tetrahedralize_geometry(shape_geometry(balls), 0.3, "/discretization/fem/max_cell_size");
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("scene.json"), std::string::npos) << message;
    EXPECT_NE(message.find("/discretization/fem/max_cell_size"), std::string::npos) << message;
  }
  // Fine enough, the same geometry passes with two pieces.
  const VolumeMesh fine = tetrahedralize_geometry(shape_geometry(balls), 0.1, "/discretization/fem/max_cell_size");
  EXPECT_EQ(volume_mesh_components(fine), 2);
}

TEST(MeshComponents, CountsSolidShellsOfASurfaceAndPiecesOfAShape) {
  EXPECT_EQ(shape_components(*two_boxes(), 0.002), 2);
  const auto hollow = make_difference({make_sphere({0, 0, 0}, 1), make_sphere({0, 0, 0}, 0.5)});
  EXPECT_EQ(shape_components(*hollow, 0.05), 1);
}

}  // namespace
}  // namespace altfem
