// Hexahedra split into 12 tetrahedra each about their centroids (tetrahedra_of_hexahedra):
// the volume is kept exactly, the tetrahedra conform across cells (every inner triangle
// is shared by exactly two of them, the boundary's triangles cover the box's surface),
// and a cell that is not star-shaped about its centroid is named.
#include "shared/mesh/tetrahedra_of_hexahedra.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <map>
#include <random>

#include "shared/common/error.hpp"
#include "shared/mesh/structured_grid.hpp"

namespace altfem {
namespace {

// Each tetrahedron face by its sorted node indices, with how many tetrahedra have it.
std::map<std::array<int, 3>, int> triangle_counts(const VolumeMesh& tetrahedra) {
  std::map<std::array<int, 3>, int> counts;
  for (Eigen::Index cell = 0; cell < tetrahedra.cells.rows(); ++cell)
    for (int skipped = 0; skipped < 4; ++skipped) {
      std::array<int, 3> face;
      int k = 0;
      for (int corner = 0; corner < 4; ++corner)
        if (corner != skipped) face[k++] = tetrahedra.cells(cell, corner);
      std::sort(face.begin(), face.end());
      ++counts[face];
    }
  return counts;
}

double triangle_area(const VolumeMesh& mesh, const std::array<int, 3>& face) {
  const Eigen::Vector3d a = mesh.nodes.row(face[0]), b = mesh.nodes.row(face[1]), c = mesh.nodes.row(face[2]);
  return 0.5 * (b - a).cross(c - a).norm();
}

void expect_conforming_and_covering(const VolumeMesh& tetrahedra, double surface_area) {
  double boundary_area = 0;
  for (const auto& [face, count] : triangle_counts(tetrahedra)) {
    ASSERT_LE(count, 2) << "a triangle of more than two tetrahedra";
    if (count == 1) boundary_area += triangle_area(tetrahedra, face);
  }
  EXPECT_NEAR(boundary_area, surface_area, 1e-12 * surface_area) << "a triangle met by one tetrahedron only inside";
}

const Eigen::AlignedBox3d box{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(3, 2, 1)};
constexpr double box_surface = 2 * (3 * 2 + 3 * 1 + 2 * 1);

TEST(TetrahedraOfHexahedra, AGridKeepsItsVolumeAndConforms) {
  const VolumeMesh hexahedra = structured_grid(box, Eigen::Vector3i(3, 2, 2), ElementType::hex8);
  const VolumeMesh tetrahedra = tetrahedra_of_hexahedra(hexahedra);
  EXPECT_EQ(tetrahedra.cells.rows(), 12 * hexahedra.cells.rows());
  EXPECT_EQ(tetrahedra.nodes.rows(), hexahedra.nodes.rows() + hexahedra.cells.rows());
  EXPECT_NO_THROW(check_volume_mesh(tetrahedra, "split grid"));
  EXPECT_NEAR(volume_mesh_volume(tetrahedra), 6.0, 1e-13);
  expect_conforming_and_covering(tetrahedra, box_surface);
}

// Inner nodes moved at random: the faces are no longer planar, each is split by the
// diagonal through its smallest node index from both sides, so the cells still conform.
TEST(TetrahedraOfHexahedra, WarpedCellsConformThroughTheSmallestIndexDiagonal) {
  VolumeMesh hexahedra = structured_grid(box, Eigen::Vector3i(3, 2, 2), ElementType::hex8);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> shift(-0.15, 0.15);
  for (Eigen::Index node = 0; node < hexahedra.nodes.rows(); ++node) {
    const Eigen::Vector3d x = hexahedra.nodes.row(node);
    if ((x - box.min()).minCoeff() > 1e-12 && (box.max() - x).minCoeff() > 1e-12)
      for (int axis = 0; axis < 3; ++axis) hexahedra.nodes(node, axis) += shift(random);
  }
  const VolumeMesh tetrahedra = tetrahedra_of_hexahedra(hexahedra);
  EXPECT_NO_THROW(check_volume_mesh(tetrahedra, "warped split grid"));
  EXPECT_NEAR(volume_mesh_volume(tetrahedra), 6.0, 1e-12) << "the boundary is unchanged, so is the volume";
  expect_conforming_and_covering(tetrahedra, box_surface);
}

TEST(TetrahedraOfHexahedra, HigherOrderCellsGiveTheirCornersOnly) {
  const VolumeMesh hexahedra = structured_grid(box, Eigen::Vector3i(3, 2, 2), ElementType::hex20);
  const VolumeMesh tetrahedra = tetrahedra_of_hexahedra(hexahedra);
  EXPECT_EQ(tetrahedra.nodes.rows(), 4 * 3 * 3 + hexahedra.cells.rows());
  EXPECT_NO_THROW(check_volume_mesh(tetrahedra, "split Hex20 grid"));
  EXPECT_NEAR(volume_mesh_volume(tetrahedra), 6.0, 1e-13);
}

TEST(TetrahedraOfHexahedra, ACellNotStarShapedAboutItsCentroidIsNamed) {
  VolumeMesh hexahedra = structured_grid(box, Eigen::Vector3i(2, 1, 1), ElementType::hex8);
  // Push the top corners of the second cell's far end deep into the cell, past its centroid.
  for (int corner : {5, 6}) hexahedra.nodes.row(hexahedra.cells(1, corner)) += Eigen::RowVector3d(-1.4, 0, -0.9);
  try {
    tetrahedra_of_hexahedra(hexahedra);
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("hexahedron 1 is not star-shaped"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace altfem
