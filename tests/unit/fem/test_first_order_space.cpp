// The first-order space inside a higher-order Lagrange mesh (first_order_space.hpp), the
// coarse level of PETSc's p-multigrid: it must hold the affine fields exactly (they are
// what algebraic multigrid's coarse spaces are built from), be one conforming space (a
// node's row the same from every cell holding it) and be 1 at its own nodes — on a refined
// grid too, where it has hanging nodes of its own.
#include <gtest/gtest.h>

#include "shared/element/reference_element.hpp"
#include "shared/element/reference_nodes.hpp"
#include "shared/fem/first_order_space.hpp"
#include "shared/mesh/hexahedral_forest.hpp"
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

// A refined grid (the middle cell of 3 × 3 × 3 split, then one of its eighths again, the
// balance splitting its neighbours): the first-order space with hanging nodes of its own.
struct RefinedGrid {
  ConstrainedHexahedralMesh grid;
  CoarseSpace space;
  int first_order_free_nodes = 0;  ///< the Hex8 grid's over the same leaves
};
RefinedGrid refined_grid(ElementType type) {
  const auto leaves = [&](ElementType of) {
    const HexahedralForest once = refine_forest(grid_forest(test::unit_cube(), Eigen::Vector3i(3, 3, 3), of), {13});
    return refine_forest(once, {13});
  };
  RefinedGrid result{forest_mesh(leaves(type)), {}, forest_mesh(leaves(ElementType::hex8)).constraints.free_nodes};
  result.space = first_order_space(result.grid.mesh, &result.grid.constraints);
  return result;
}

// The values at every node of the fine function the coarse values interpolate: the free
// nodes' from the prolongation, the hanging ones' from their masters.
Eigen::VectorXd every_node(const RefinedGrid& refined, const Eigen::VectorXd& coarse) {
  const NodeConstraints& constraints = refined.grid.constraints;
  Eigen::VectorXd values(refined.grid.mesh.nodes.rows());
  values.head(constraints.free_nodes) = refined.space.prolongation * coarse;
  for (int h = 0; h < constraints.hanging_nodes(); ++h) {
    double value = 0;
    for (size_t k = 0; k < constraints.masters[h].size(); ++k)
      value += constraints.weights[h][k] * values[constraints.masters[h][k]];
    values[constraints.free_nodes + h] = value;
  }
  return values;
}

class FirstOrderSpaceWithHangingNodes : public ::testing::TestWithParam<ElementType> {};

// Its functions are the Hex8 grid's: as many, each 1 at its node.
TEST_P(FirstOrderSpaceWithHangingNodes, HasTheFirstOrderGridsFunctions) {
  const RefinedGrid refined = refined_grid(GetParam());
  ASSERT_GT(refined.grid.constraints.hanging_nodes(), 0);
  EXPECT_EQ(refined.space.prolongation.rows(), refined.grid.constraints.free_nodes);
  EXPECT_EQ(static_cast<int>(refined.space.fine_function.size()), refined.first_order_free_nodes);
  const Eigen::SparseMatrix<double, Eigen::RowMajor> rows = refined.space.prolongation;
  for (size_t j = 0; j < refined.space.fine_function.size(); ++j) {
    ASSERT_EQ(rows.row(refined.space.fine_function[j]).nonZeros(), 1);
    EXPECT_EQ(rows.coeff(refined.space.fine_function[j], static_cast<Eigen::Index>(j)), 1.0);
  }
}

TEST_P(FirstOrderSpaceWithHangingNodes, InterpolatesAffineFieldsExactlyAtEveryNode) {
  const RefinedGrid refined = refined_grid(GetParam());
  const Eigen::Vector3d gradient(0.3, -1.7, 2.9);
  const auto field = [&](int node) { return 0.5 + gradient.dot(refined.grid.mesh.nodes.row(node)); };
  Eigen::VectorXd coarse(static_cast<Eigen::Index>(refined.space.fine_function.size()));
  for (Eigen::Index j = 0; j < coarse.size(); ++j) coarse[j] = field(refined.space.fine_function[j]);
  const Eigen::VectorXd values = every_node(refined, coarse);
  for (int node = 0; node < values.size(); ++node) EXPECT_NEAR(values[node], field(node), 1e-13) << node;
}

// Random coarse values: on every cell, coarse and fine, each node's value is the first-order
// interpolation of the cell's corners' — a function of the first-order space with hanging
// nodes, not only of the fine one.
TEST_P(FirstOrderSpaceWithHangingNodes, EveryCoarseFunctionIsFirstOrderOnEveryCell) {
  const RefinedGrid refined = refined_grid(GetParam());
  std::srand(11);
  const Eigen::VectorXd values =
      every_node(refined, Eigen::VectorXd::Random(static_cast<Eigen::Index>(refined.space.fine_function.size())));
  const VolumeMesh& mesh = refined.grid.mesh;
  const Eigen::MatrixXd nodes = reference_nodes(GetParam());
  Eigen::VectorXd corner_values(8);
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell)
    for (Eigen::Index local = 8; local < mesh.cells.cols(); ++local) {
      reference_element(ElementType::hex8).evaluate(nodes.row(local).transpose(), corner_values);
      double first_order = 0;
      for (int corner = 0; corner < 8; ++corner)
        first_order += corner_values[corner] * values[mesh.cells(cell, corner)];
      EXPECT_NEAR(values[mesh.cells(cell, local)], first_order, 1e-13) << "cell " << cell << ", node " << local;
    }
}

INSTANTIATE_TEST_SUITE_P(Quadratic, FirstOrderSpaceWithHangingNodes,
                         ::testing::Values(ElementType::hex20, ElementType::hex27),
                         [](const auto& info) { return std::string(element_name(info.param)); });

TEST(FirstOrderSpaceOfAFirstOrderMesh, IsEmpty) {
  EXPECT_TRUE(
      first_order_space(structured_grid(test::unit_cube(), Eigen::Vector3i(2, 2, 2), ElementType::hex8)).empty());
  EXPECT_TRUE(
      first_order_space(structured_grid(test::unit_cube(), Eigen::Vector3i(2, 2, 2), ElementType::tet4)).empty());
}

}  // namespace
}  // namespace altfem
