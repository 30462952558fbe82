// Face neighbours of conforming meshes (shared/mesh/face_neighbours.hpp): every face of a
// grid's tetrahedra or hexahedra meets the one across it both ways, the faces left
// unmatched are the boundary's, and copies of the nodes on a plane keep its sides apart.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "shared/element/element_faces.hpp"
#include "shared/mesh/boundary_surface.hpp"
#include "shared/mesh/face_neighbours.hpp"
#include "shared/mesh/structured_grid.hpp"

namespace altfem {
namespace {

const Eigen::AlignedBox3d unit_box(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());

// Faces without a neighbour, checking that every matched pair points back and shares its nodes.
int unmatched_faces(const VolumeMesh& mesh) {
  const auto faces = element_faces(element_shape(mesh.element_type));
  const int corners = face_corner_count(element_shape(mesh.element_type));
  const auto face_count = static_cast<int>(faces.size());
  const std::vector<FaceNeighbour> neighbours = face_neighbours(mesh);
  EXPECT_EQ(neighbours.size(), static_cast<std::size_t>(mesh.cells.rows() * face_count));
  const auto nodes_of = [&](int cell, int face) {
    std::vector<int> nodes;
    for (int c = 0; c < corners; ++c) nodes.push_back(mesh.cells(cell, faces[face][c]));
    std::sort(nodes.begin(), nodes.end());
    return nodes;
  };
  int unmatched = 0;
  for (int cell = 0; cell < mesh.cells.rows(); ++cell)
    for (int f = 0; f < face_count; ++f) {
      const FaceNeighbour across = neighbours[static_cast<std::size_t>(cell * face_count + f)];
      if (across.cell < 0) {
        ++unmatched;
        continue;
      }
      EXPECT_NE(across.cell, cell);
      const FaceNeighbour back = neighbours[static_cast<std::size_t>(across.cell * face_count + across.face)];
      EXPECT_EQ(back.cell, cell);
      EXPECT_EQ(back.face, f);
      EXPECT_EQ(nodes_of(across.cell, across.face), nodes_of(cell, f));
    }
  return unmatched;
}

TEST(FaceNeighbours, AGridsFacesMeetTheirNeighboursAndOnlyTheBoundaryIsLeft) {
  const VolumeMesh tetrahedra = structured_grid(unit_box, Eigen::Vector3i(3, 2, 4), ElementType::tet4);
  EXPECT_EQ(unmatched_faces(tetrahedra), boundary_surface(tetrahedra).surface.triangles.rows());
  const VolumeMesh hexahedra = structured_grid(unit_box, Eigen::Vector3i(3, 2, 4), ElementType::hex8);
  EXPECT_EQ(unmatched_faces(hexahedra), 2 * (3 * 2 + 2 * 4 + 3 * 4));
}

TEST(FaceNeighbours, CopiesOfTheNodesOnAPlaneKeepItsSidesApart) {
  VolumeMesh mesh = structured_grid(unit_box, Eigen::Vector3i(2, 1, 1), ElementType::hex8);
  // The cells x < 0.5 take copies of the nodes on x = 0.5.
  const Eigen::Index count = mesh.nodes.rows();
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell) {
    if (mesh.nodes(mesh.cells(cell, 0), 0) > 0.25) continue;
    for (Eigen::Index a = 0; a < mesh.cells.cols(); ++a) {
      const int node = mesh.cells(cell, a);
      if (std::abs(mesh.nodes(node, 0) - 0.5) > 1e-12) continue;
      mesh.nodes.conservativeResize(mesh.nodes.rows() + 1, 3);
      mesh.nodes.row(mesh.nodes.rows() - 1) = mesh.nodes.row(node);
      mesh.cells(cell, a) = static_cast<int>(mesh.nodes.rows() - 1);
    }
  }
  ASSERT_EQ(mesh.nodes.rows(), count + 4);
  EXPECT_EQ(unmatched_faces(mesh), 12);
}

}  // namespace
}  // namespace altfem
