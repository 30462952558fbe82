// Plain cells of a converted mesh are recognised and a Tet4/Hex8 corner order is
// recovered from the polyhedral faces alone: the original cell's nodes (the conversion
// keeps a linear mesh's numbering), in a valid VTK order — the geometry map's Jacobian
// positive at every corner (a rotation of the base is as good as the original order).
#include <gtest/gtest.h>

#include <algorithm>

#include "polyhedral/plain_cells.hpp"
#include "shared/element/geometry_map.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"
#include "shared/mesh/structured_grid.hpp"

namespace altfem::harmonic {
namespace {

class PlainCells : public ::testing::TestWithParam<ElementType> {};

TEST_P(PlainCells, RecoverTheOriginalCornerOrder) {
  const Eigen::AlignedBox3d box(Eigen::Vector3d::Zero(), Eigen::Vector3d(2, 1, 1.5));
  const VolumeMesh volume = structured_grid(box, {2, 2, 1}, GetParam());
  const PolyhedralMesh mesh = polyhedral_mesh_from_volume_mesh(volume);
  ASSERT_EQ(mesh.cell_count(), volume.cells.rows());
  for (int cell = 0; cell < mesh.cell_count(); ++cell) {
    const auto plain = plain_cell(mesh, cell);
    ASSERT_TRUE(plain.has_value()) << "cell " << cell;
    EXPECT_EQ(plain->type, GetParam());
    std::vector<int> recovered = plain->nodes, original;
    for (Eigen::Index corner = 0; corner < volume.cells.cols(); ++corner)
      original.push_back(volume.cells(cell, corner));
    std::sort(recovered.begin(), recovered.end());
    std::sort(original.begin(), original.end());
    EXPECT_EQ(recovered, original) << "cell " << cell;
    const ReferenceElement& element = reference_element(GetParam());
    const Eigen::MatrixXd nodes = mesh.nodes(plain->nodes, Eigen::all);
    for (Eigen::Index corner = 0; corner < element.nodes().rows(); ++corner)
      EXPECT_GT(map_jacobian(element, nodes, element.nodes().row(corner).transpose()).determinant(), 0)
          << "cell " << cell << ", corner " << corner;
  }
}

INSTANTIATE_TEST_SUITE_P(HarmonicMesh, PlainCells, ::testing::Values(ElementType::tet4, ElementType::hex8),
                         [](const auto& info) { return std::string(element_name(info.param)); });

}  // namespace
}  // namespace altfem::harmonic
