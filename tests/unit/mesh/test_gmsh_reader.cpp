#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <sstream>
#include <string>

#include "shared/common/error.hpp"
#include "shared/mesh/bounding_box.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem {
namespace {

std::string volume_file(const std::string& name) { return std::string(ALTFEM_SOURCE_DIR) + "/data/volume/" + name; }

Eigen::Vector3d node(const VolumeMesh& mesh, Eigen::Index cell, int local) {
  return mesh.nodes.row(mesh.cells(cell, local)).transpose();
}

// docs/conventions.md: VTK node order. Tet10 edges (0,1),(1,2),(0,2),(0,3),(1,3),(2,3).
void expect_tet10_midpoints(const VolumeMesh& mesh) {
  constexpr std::array<std::array<int, 2>, 6> edges{{{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}}};
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell)
    for (int e = 0; e < 6; ++e) {
      const Eigen::Vector3d midpoint = 0.5 * (node(mesh, cell, edges[e][0]) + node(mesh, cell, edges[e][1]));
      ASSERT_LT((node(mesh, cell, 4 + e) - midpoint).norm(), 1e-12) << "cell " << cell << " edge node " << 4 + e;
    }
}

// VTK Hex20 edges, then (Hex27) face centres x-, x+, y-, y+, z-, z+ and the body centre.
void expect_hex_midpoints(const VolumeMesh& mesh, bool with_faces) {
  constexpr std::array<std::array<int, 2>, 12> edges{
      {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}}};
  constexpr std::array<std::array<int, 4>, 6> faces{
      {{0, 3, 7, 4}, {1, 2, 6, 5}, {0, 1, 5, 4}, {3, 2, 6, 7}, {0, 1, 2, 3}, {4, 5, 6, 7}}};
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell) {
    for (int e = 0; e < 12; ++e) {
      const Eigen::Vector3d midpoint = 0.5 * (node(mesh, cell, edges[e][0]) + node(mesh, cell, edges[e][1]));
      ASSERT_LT((node(mesh, cell, 8 + e) - midpoint).norm(), 1e-12) << "cell " << cell << " edge node " << 8 + e;
    }
    if (!with_faces) continue;
    Eigen::Vector3d body = Eigen::Vector3d::Zero();
    for (int f = 0; f < 6; ++f) {
      Eigen::Vector3d centre = Eigen::Vector3d::Zero();
      for (const int corner : faces[f]) centre += node(mesh, cell, corner) / 4;
      ASSERT_LT((node(mesh, cell, 20 + f) - centre).norm(), 1e-12) << "cell " << cell << " face node " << 20 + f;
      body += centre / 6;
    }
    ASSERT_LT((node(mesh, cell, 26) - body).norm(), 1e-12) << "cell " << cell;
  }
}

struct DataMesh {
  const char* file;
  ElementType type;
  Eigen::Index cells;
  Eigen::Index nodes;
};

TEST(GmshReader, ReadsEveryShippedCubeWithUnitVolume) {
  const std::array<DataMesh, 4> meshes{{{"cube_tet4_24.msh", ElementType::tet4, 24, 14},
                                        {"cube_tet10_24.msh", ElementType::tet10, 24, 63},
                                        {"cube_hex8_8.msh", ElementType::hex8, 8, 27},
                                        {"cube_hex27_8.msh", ElementType::hex27, 8, 125}}};
  for (const auto& expected : meshes) {
    SCOPED_TRACE(expected.file);
    const VolumeMesh mesh = read_volume_mesh(volume_file(expected.file));
    EXPECT_EQ(mesh.element_type, expected.type);
    EXPECT_EQ(mesh.cells.rows(), expected.cells);
    EXPECT_EQ(mesh.nodes.rows(), expected.nodes);
    EXPECT_NEAR(volume_mesh_volume(mesh), 1.0, 1e-12);
    const BoundingBox box = bounding_box(mesh.nodes);
    EXPECT_NEAR(box.diagonal(), std::sqrt(3.0), 1e-12);
  }
}

TEST(GmshReader, MidNodesLieAtEdgeAndFaceMidpointsInVtkOrder) {
  expect_tet10_midpoints(read_volume_mesh(volume_file("cube_tet10_24.msh")));
  expect_hex_midpoints(read_volume_mesh(volume_file("cube_hex27_8.msh")), true);
}

TEST(GmshReader, ReadsTheSphereWithAPolyhedralVolume) {
  const VolumeMesh mesh = read_volume_mesh(volume_file("sphere_tet4_593.msh"));
  EXPECT_EQ(mesh.cells.rows(), 593);
  const double ball = 4.0 / 3.0 * M_PI * 0.125;
  // An inscribed polyhedron of a radius-0.5 ball: a little less than the ball.
  EXPECT_LT(volume_mesh_volume(mesh), ball);
  EXPECT_GT(volume_mesh_volume(mesh), 0.9 * ball);
  for (Eigen::Index i = 0; i < mesh.nodes.rows(); ++i) ASSERT_LE(mesh.nodes.row(i).norm(), 0.5 + 1e-9);
}

// MSH 2.2: a Tet10 with Gmsh's edge order (nodes 9 and 10 are edges (2,3) and (1,3)),
// a boundary triangle that is ignored, and node tags that are not 1..n.
constexpr const char* tet10_v22 = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$Nodes
11
10 0 0 0
20 1 0 0
30 0 1 0
40 0 0 1
50 0.5 0 0
60 0.5 0.5 0
70 0 0.5 0
80 0 0 0.5
90 0 0.5 0.5
100 0.5 0 0.5
110 7 7 7
$EndNodes
$Elements
2
1 2 2 0 1 10 20 30
2 11 2 0 1 10 20 30 40 50 60 70 80 90 100
$EndElements
)";

TEST(GmshReader, Msh22Tet10IsPermutedToVtkOrderAndUnusedNodesDropped) {
  const VolumeMesh mesh = parse_gmsh(tet10_v22, "tet10.msh");
  check_volume_mesh(mesh, "tet10.msh");
  EXPECT_EQ(mesh.element_type, ElementType::tet10);
  ASSERT_EQ(mesh.cells.rows(), 1);
  EXPECT_EQ(mesh.nodes.rows(), 10);  // tag 110 belongs to no cell
  expect_tet10_midpoints(mesh);
  EXPECT_NEAR(volume_mesh_volume(mesh), 1.0 / 6.0, 1e-15);
}

// A unit-cube Hex20 in Gmsh's order: edges (0,1),(0,3),(0,4),(1,2),(1,5),(2,3),(2,6),(3,7),(4,5),(4,7),(5,6),(6,7).
TEST(GmshReader, Msh22Hex20IsPermutedToVtkOrder) {
  const double corners[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const int gmsh_edges[12][2] = {{0, 1}, {0, 3}, {0, 4}, {1, 2}, {1, 5}, {2, 3},
                                 {2, 6}, {3, 7}, {4, 5}, {4, 7}, {5, 6}, {6, 7}};
  std::ostringstream text;
  text << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n20\n";
  for (int i = 0; i < 8; ++i)
    text << i + 1 << " " << corners[i][0] << " " << corners[i][1] << " " << corners[i][2] << "\n";
  for (int e = 0; e < 12; ++e) {
    text << 9 + e;
    for (int axis = 0; axis < 3; ++axis)
      text << " " << 0.5 * (corners[gmsh_edges[e][0]][axis] + corners[gmsh_edges[e][1]][axis]);
    text << "\n";
  }
  text << "$EndNodes\n$Elements\n1\n1 17 0";
  for (int i = 1; i <= 20; ++i) text << " " << i;
  text << "\n$EndElements\n";
  const VolumeMesh mesh = parse_gmsh(text.str(), "hex20.msh");
  check_volume_mesh(mesh, "hex20.msh");
  EXPECT_EQ(mesh.element_type, ElementType::hex20);
  expect_hex_midpoints(mesh, false);
  EXPECT_NEAR(volume_mesh_volume(mesh), 1.0, 1e-14);
}

TEST(GmshReader, Msh41WithParametricNodesAndSparseTags) {
  constexpr const char* text = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$PhysicalNames
1
3 1 "solid"
$EndPhysicalNames
$Nodes
2 4 1 40
1 1 1 3
10
20
30
0 0 0 0.1
2 0 0 0.2
0 2 0 0.3
3 1 0 1
40
0 0 2
$EndNodes
$Elements
1 1 7 7
3 1 4 1
7 10 20 30 40
$EndElements
)";
  const VolumeMesh mesh = parse_gmsh(text, "tet.msh");
  check_volume_mesh(mesh, "tet.msh");
  EXPECT_EQ(mesh.cells.rows(), 1);
  EXPECT_NEAR(volume_mesh_volume(mesh), 8.0 / 6.0, 1e-15);
}

TEST(GmshReader, ErrorsNameFileAndLine) {
  const auto message = [](const std::string& text) {
    try {
      parse_gmsh(text, "m.msh");
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(""), "m.msh: line 1: empty file, expected a Gmsh MSH file starting with $MeshFormat");
  EXPECT_EQ(message("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0\n"),
            "m.msh: line 6: file ends early: expected a node's z coordinate");
  EXPECT_EQ(message("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0 0\n$EndNodes\n"),
            "m.msh: line 7: the file has no $Elements section");
  EXPECT_EQ(message("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 2 1 2\n3 1 0 1\n1\n0 0 0\n$EndNodes\n"),
            "m.msh: line 8: wrong count: 2 nodes declared, the blocks hold 1");
  EXPECT_EQ(message("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0 0\n$EndNodes\n$Elements\n"
                    "2\n1 4 0 1 1 1 1\n2 5 0 1 1 1 1 1 1 1 1\n$EndElements\n"),
            "m.msh: line 11: the mesh mixes tet4 and hex8 cells, altfem reads one cell type per mesh");
}

}  // namespace
}  // namespace altfem
