// The elements' mean Cauchy stress (output): under a homogeneous deformation F = G
// every element of a distorted mesh holds σ = P(G) Gᵀ / det G exactly.
#include <gtest/gtest.h>

#include "tests/unit/assembly/assembly_fixture.hpp"

namespace altfem {
namespace {

class MeanStress : public ::testing::TestWithParam<ElementType> {};

TEST_P(MeanStress, HomogeneousDeformationGivesTheExactCauchyStressInEveryElement) {
  const test::AssemblyProblem problem(GetParam(), {2, 2, 3}, MaterialModel::stable_neo_hookean);
  Eigen::Matrix3d G;
  G << 1.05, 0.02, -0.01, 0.03, 0.97, 0.04, -0.02, 0.01, 1.1;
  Eigen::VectorXd u(3 * problem.mesh.nodes.rows());
  for (Eigen::Index node = 0; node < problem.mesh.nodes.rows(); ++node)
    u.segment<3>(3 * node) = (G - Eigen::Matrix3d::Identity()) * problem.mesh.nodes.row(node).transpose();
  const Eigen::Matrix3d expected = problem.material->pk1(G) * G.transpose() / G.determinant();
  // Cauchy stress is symmetric for a hyperelastic material.
  ASSERT_LT((expected - expected.transpose()).norm(), 1e-9 * expected.norm());
  const Eigen::MatrixXd stresses = problem.assembler->mean_cauchy_stress(u);
  ASSERT_EQ(stresses.rows(), problem.elements.size());
  for (Eigen::Index e = 0; e < stresses.rows(); ++e) {
    const Eigen::RowVectorXd row = stresses.row(e);  // a contiguous copy of the row
    const Eigen::Matrix3d sigma = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(row.data());
    EXPECT_LT((sigma - expected).norm(), 1e-10 * expected.norm()) << "element " << e;
  }
}

INSTANTIATE_TEST_SUITE_P(Elements, MeanStress,
                         ::testing::Values(ElementType::tet4, ElementType::tet10, ElementType::hex8,
                                           ElementType::hex20),
                         [](const auto& info) { return std::string(element_name(info.param)); });

}  // namespace
}  // namespace altfem
