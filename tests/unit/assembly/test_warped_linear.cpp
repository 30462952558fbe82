// Stiffness warping of linear nodal elements (shared/assembly/warped_linear_discretization.hpp)
// on a distorted Hex8 grid: no force under a large rigid rotation (the plain linear
// stiffness gives one; both printed), the patch test under a rotated affine deformation,
// the warped tangent R K Rᵀ, and K itself at rest.
#include <gtest/gtest.h>

#include <cstdio>

#include "shared/assembly/warped_linear_discretization.hpp"
#include "tests/unit/assembly/assembly_fixture.hpp"

namespace altfem {
namespace {

struct WarpedProblem {
  test::AssemblyProblem problem{ElementType::hex8, {3, 2, 2}, MaterialModel::linear};
  std::unique_ptr<WarpedLinearDiscretization> warped;

  WarpedProblem() {
    DiscretizationParts parts;
    parts.elements = problem.elements;
    parts.materials = {problem.material.get()};
    warped = std::make_unique<WarpedLinearDiscretization>(std::move(parts), problem.mesh.nodes);
  }
  // u = (G − I) X + t at every node.
  Eigen::VectorXd affine(const Eigen::Matrix3d& G, const Eigen::Vector3d& t) const {
    return test::nodal_values(problem.mesh, [&](const Eigen::Vector3d& x) -> Eigen::Vector3d {
      return (G - Eigen::Matrix3d::Identity()) * x + t;
    });
  }
};

Eigen::Matrix3d large_rotation() {
  return Eigen::AngleAxisd(1.3, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
}

TEST(WarpedLinear, RigidRotationGivesNoForce) {
  const WarpedProblem setup;
  const Eigen::VectorXd u = setup.affine(large_rotation(), {0.2, -0.1, 0.3});
  Eigen::VectorXd warped, linear;
  setup.warped->gradient(u, warped);
  setup.problem.assembler->gradient(u, linear);
  std::printf("  rigid rotation by 1.3 rad: |f| linear %.3e, warped %.3e (relative %.2e); warped energy %.2e\n",
              linear.norm(), warped.norm(), warped.norm() / linear.norm(), setup.warped->energy(u));
  EXPECT_GT(linear.norm(), 1e2);
  EXPECT_LT(warped.norm(), 1e-10 * linear.norm());
  EXPECT_LT(std::abs(setup.warped->energy(u)), 1e-10 * 0.5 * u.dot(linear));
}

TEST(WarpedLinear, RotatedAffineDeformationPassesThePatchTest) {
  // x = Q S X: every element's rotation is polar(Q S), so the interior nodes, whose
  // elements all carry the same constant stress, feel no force.
  const WarpedProblem setup;
  Eigen::Matrix3d stretch;
  stretch << 1.02, 0.01, -0.005, 0.004, 0.99, 0.006, -0.003, 0.008, 1.015;
  const Eigen::VectorXd u = setup.affine(large_rotation() * stretch, {0.1, 0.2, -0.3});
  Eigen::VectorXd force;
  setup.warped->gradient(u, force);
  double interior = 0;
  int interior_nodes = 0;
  for (Eigen::Index node = 0; node < setup.problem.mesh.nodes.rows(); ++node) {
    const Eigen::Array3d x = setup.problem.mesh.nodes.row(node).transpose();
    if ((x > 1e-9).all() && (x < 1 - 1e-9).all())
      interior = std::max(interior, force.segment<3>(3 * node).norm()), ++interior_nodes;
  }
  std::printf("  rotated affine field: %d interior nodes, max interior |f| / max |f| = %.2e\n", interior_nodes,
              interior / force.cwiseAbs().maxCoeff());
  ASSERT_GT(interior_nodes, 0);
  EXPECT_LT(interior, 1e-10 * force.cwiseAbs().maxCoeff());
}

TEST(WarpedLinear, TangentIsTheRotatedStiffnessAndKAtRest) {
  const WarpedProblem setup;
  Eigen::SparseMatrix<double> stiffness = setup.warped->hessian_pattern(), rest = stiffness, rotated = stiffness;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(setup.warped->dof_count());
  setup.problem.assembler->hessian(zero, stiffness);
  setup.warped->hessian(zero, rest, false);
  EXPECT_LT((Eigen::MatrixXd(rest) - Eigen::MatrixXd(stiffness)).cwiseAbs().maxCoeff(),
            1e-12 * Eigen::MatrixXd(stiffness).cwiseAbs().maxCoeff());
  // Under a rigid rotation Q every R_e = Q: the tangent is diag(Q) K diag(Q)ᵀ.
  const Eigen::Matrix3d rotation = large_rotation();
  setup.warped->hessian(setup.affine(rotation, Eigen::Vector3d::Zero()), rotated, false);
  const Eigen::Index nodes = setup.problem.mesh.nodes.rows();
  Eigen::MatrixXd block_rotation = Eigen::MatrixXd::Zero(3 * nodes, 3 * nodes);
  for (Eigen::Index node = 0; node < nodes; ++node) block_rotation.block<3, 3>(3 * node, 3 * node) = rotation;
  const Eigen::MatrixXd expected = block_rotation * Eigen::MatrixXd(stiffness) * block_rotation.transpose();
  EXPECT_LT((Eigen::MatrixXd(rotated) - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
}

TEST(WarpedLinear, RejectsANonlinearMaterial) {
  const test::AssemblyProblem problem{ElementType::hex8, {1, 1, 1}, MaterialModel::neo_hookean};
  DiscretizationParts parts;
  parts.elements = problem.elements;
  parts.materials = {problem.material.get()};
  EXPECT_THROW(WarpedLinearDiscretization(std::move(parts), problem.mesh.nodes), std::invalid_argument);
}

}  // namespace
}  // namespace altfem
