#include "shared/common/eigen_decompositions.hpp"
#include "shared/material/project_spd.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <limits>

#include "shared/common/error.hpp"
#include "tests/unit/material/deformation_samples.hpp"

namespace altfem {
namespace {

Eigen::MatrixXd random_orthogonal(int n, std::mt19937& random) {
  std::normal_distribution<double> normal;
  Eigen::MatrixXd A(n, n);
  for (double& entry : A.reshaped()) entry = normal(random);
  return Eigen::HouseholderQR<Eigen::MatrixXd>(A).householderQ();
}

double smallest_eigenvalue(const Eigen::MatrixXd& A) {
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(A, Eigen::EigenvaluesOnly).eigenvalues().minCoeff();
}

TEST(ProjectToSpd, ClampsExactlyOnAHandBuiltMatrix) {
  std::mt19937 random(29);
  const Eigen::MatrixXd Q = random_orthogonal(5, random);
  const Eigen::VectorXd eigenvalues = (Eigen::VectorXd(5) << -2.0, -1e-3, 0.5, 3.0, 7.0).finished();
  const Eigen::MatrixXd A = Q * eigenvalues.asDiagonal() * Q.transpose();

  Eigen::MatrixXd projected = A;
  project_to_spd(projected);
  const Eigen::VectorXd clamped = (Eigen::VectorXd(5) << 0.0, 0.0, 0.5, 3.0, 7.0).finished();
  EXPECT_LE((projected - Q * clamped.asDiagonal() * Q.transpose()).norm(), 1e-13);

  projected = A;
  project_to_spd(projected, 1.0);
  const Eigen::VectorXd raised = (Eigen::VectorXd(5) << 1.0, 1.0, 1.0, 3.0, 7.0).finished();
  EXPECT_LE((projected - Q * raised.asDiagonal() * Q.transpose()).norm(), 1e-13);
}

TEST(ProjectToSpd, ResultIsPositiveSemiDefinite) {
  std::mt19937 random(31);
  std::normal_distribution<double> normal;
  for (int n : {3, 12, 30}) {
    Eigen::MatrixXd A(n, n);
    for (double& entry : A.reshaped()) entry = 1e6 * normal(random);
    A = (A + A.transpose()).eval();
    ASSERT_LT(smallest_eigenvalue(A), 0.0);
    project_to_spd(A);
    EXPECT_GE(smallest_eigenvalue(A), -1e-12 * A.norm()) << "n = " << n;
  }
}

TEST(ProjectToSpd, LeavesSpdMatrixUntouched) {
  std::mt19937 random(37);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd B(10, 10);
  for (double& entry : B.reshaped()) entry = normal(random);
  const Eigen::MatrixXd A = B.transpose() * B + 0.1 * Eigen::MatrixXd::Identity(10, 10);
  Eigen::MatrixXd projected = A;
  project_to_spd(projected);
  EXPECT_TRUE(projected == A);
  // A fixed-size block of a larger matrix goes through Eigen::Ref.
  Eigen::MatrixXd big = Eigen::MatrixXd::Zero(12, 12);
  big.topLeftCorner(10, 10) = -A;
  project_to_spd(big.topLeftCorner(10, 10));
  EXPECT_LE(big.norm(), 1e-12 * A.norm());
}

TEST(ProjectToSpd, FixedSizeTangentOfAnInvertedElement) {
  const auto material = make_material(MaterialModel::stable_neo_hookean, 1e6, 0.4, 1000.0);
  Eigen::Matrix3d P;
  Matrix9d dPdF;
  material->pk1_and_tangent(Eigen::Vector3d(1.1, 0.9, -0.5).asDiagonal(), P, dPdF);
  ASSERT_LT(smallest_eigenvalue(dPdF), 0.0);
  Matrix9d projected = dPdF;
  project_to_spd(projected);
  EXPECT_GE(smallest_eigenvalue(projected), -1e-12 * dPdF.norm());
  // Same answer as the dynamic-size version.
  Eigen::MatrixXd dynamic = dPdF;
  project_to_spd(dynamic);
  EXPECT_LE((dynamic - projected).norm(), 1e-12 * dPdF.norm());
  // SPD input comes back bit for bit.
  const Matrix9d spd = projected + Matrix9d::Identity();
  Matrix9d copy = spd;
  project_to_spd(copy);
  EXPECT_TRUE(copy == spd);
}

TEST(ProjectToSpd, RejectsNonFiniteInput) {
  Matrix9d A = Matrix9d::Identity();
  A(3, 4) = A(4, 3) = std::numeric_limits<double>::infinity();
  EXPECT_THROW(project_to_spd(A), NumericalError);
}

}  // namespace
}  // namespace altfem
