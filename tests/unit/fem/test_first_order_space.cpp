// The first-order space inside a higher-order Lagrange mesh (first_order_space.hpp), the
// coarse level of PETSc's p-multigrid: it must hold the affine fields exactly (they are
// what algebraic multigrid's coarse spaces are built from), be one conforming space (a
// node's row the same from every cell holding it) and be 1 at its own nodes.
#include <gtest/gtest.h>

#include "shared/element/reference_element.hpp"
#include "shared/element/reference_nodes.hpp"
#include "shared/fem/first_order_space.hpp"
#include "tests/unit/fem/test_meshes.hpp"

namespace altfem {
namespace {

class FirstOrderSpace : public ::testing::TestWithParam<ElementType> {};

// Trilinear hexahedra (interior corners moved) and straight tetrahedra: an affine
// field of x is a first-order field on both.
VolumeMesh distorted(ElementType type) {
  return test::distorted_grid(test::unit_cube(), Eigen::Vector3i(3, 2, 2), type, 0.2, 7);
}

TEST_P(FirstOrderSpace, InterpolatesAffineFieldsExactly) {
  const VolumeMesh mesh = distorted(GetParam());
  const CoarseSpace space = first_order_space(mesh);
  ASSERT_FALSE(space.empty());
  const Eigen::Vector3d gradient(0.3, -1.7, 2.9);
  const auto field = [&](Eigen::Index node) { return 0.5 + gradient.dot(mesh.nodes.row(node)); };
  Eigen::VectorXd coarse(static_cast<Eigen::Index>(space.fine_function.size()));
  for (Eigen::Index j = 0; j < coarse.size(); ++j) coarse[j] = field(space.fine_function[j]);
  const Eigen::VectorXd fine = space.prolongation * coarse;
  ASSERT_EQ(fine.size(), mesh.nodes.rows());
  for (Eigen::Index node = 0; node < fine.size(); ++node) EXPECT_NEAR(fine[node], field(node), 1e-13) << node;
  const Eigen::VectorXd row_sums = space.prolongation * Eigen::VectorXd::Ones(coarse.size());
  EXPECT_LT((row_sums.array() - 1).abs().maxCoeff(), 1e-14);
}

TEST_P(FirstOrderSpace, EveryCellHoldingANodeGivesItsRow) {
  const VolumeMesh mesh = distorted(GetParam());
  const CoarseSpace space = first_order_space(mesh);
  const Eigen::SparseMatrix<double, Eigen::RowMajor> rows = space.prolongation;
  std::vector<int> coarse_of_node(static_cast<size_t>(mesh.nodes.rows()), -1);
  for (size_t j = 0; j < space.fine_function.size(); ++j) coarse_of_node[space.fine_function[j]] = static_cast<int>(j);
  const ElementType first =
      element_shape(GetParam()) == ElementShape::tetrahedron ? ElementType::tet4 : ElementType::hex8;
  const Eigen::MatrixXd nodes = reference_nodes(GetParam());
  const int corners = element_corner_count(GetParam());
  Eigen::VectorXd values(corners);
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell)
    for (Eigen::Index local = 0; local < mesh.cells.cols(); ++local) {
      reference_element(first).evaluate(nodes.row(local).transpose(), values);
      Eigen::VectorXd from_cell = Eigen::VectorXd::Zero(rows.cols());
      for (int corner = 0; corner < corners; ++corner)
        from_cell[coarse_of_node[mesh.cells(cell, corner)]] = values[corner];
      const Eigen::VectorXd row = rows.row(mesh.cells(cell, local)).transpose();
      EXPECT_LT((row - from_cell).cwiseAbs().maxCoeff(), 1e-14) << "cell " << cell << ", node " << local;
    }
}

TEST_P(FirstOrderSpace, IsOneAtItsOwnNodes) {
  const VolumeMesh mesh = distorted(GetParam());
  const CoarseSpace space = first_order_space(mesh);
  const Eigen::SparseMatrix<double, Eigen::RowMajor> rows = space.prolongation;
  const int corners = element_corner_count(GetParam());
  // Its nodes are the cells' corners, each once.
  std::vector<int> corner_nodes;
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell)
    for (int corner = 0; corner < corners; ++corner) corner_nodes.push_back(mesh.cells(cell, corner));
  std::sort(corner_nodes.begin(), corner_nodes.end());
  corner_nodes.erase(std::unique(corner_nodes.begin(), corner_nodes.end()), corner_nodes.end());
  EXPECT_EQ(corner_nodes, space.fine_function);
  for (size_t j = 0; j < space.fine_function.size(); ++j) {
    ASSERT_EQ(rows.row(space.fine_function[j]).nonZeros(), 1);
    EXPECT_EQ(rows.coeff(space.fine_function[j], static_cast<Eigen::Index>(j)), 1.0);
  }
}

INSTANTIATE_TEST_SUITE_P(HigherOrder, FirstOrderSpace,
                         ::testing::Values(ElementType::tet10, ElementType::tet20, ElementType::hex20,
                                           ElementType::hex27),
                         [](const auto& info) { return std::string(element_name(info.param)); });

// A refined grid's hanging nodes belong to their masters: no first-order space there.
TEST(FirstOrderSpaceWithHangingNodes, IsEmpty) {
  const VolumeMesh mesh = structured_grid(test::unit_cube(), Eigen::Vector3i(2, 2, 2), ElementType::hex20);
  NodeConstraints constraints;
  constraints.free_nodes = static_cast<int>(mesh.nodes.rows()) - 1;
  constraints.masters = {{0, 1}};
  constraints.weights = {{0.5, 0.5}};
  EXPECT_TRUE(first_order_space(mesh, &constraints).empty());
  EXPECT_FALSE(first_order_space(mesh, nullptr).empty());
}

TEST(FirstOrderSpaceOfAFirstOrderMesh, IsEmpty) {
  EXPECT_TRUE(
      first_order_space(structured_grid(test::unit_cube(), Eigen::Vector3i(2, 2, 2), ElementType::hex8)).empty());
  EXPECT_TRUE(
      first_order_space(structured_grid(test::unit_cube(), Eigen::Vector3i(2, 2, 2), ElementType::tet4)).empty());
}

}  // namespace
}  // namespace altfem
