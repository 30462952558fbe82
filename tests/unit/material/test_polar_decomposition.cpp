#include "shared/material/polar_decomposition.hpp"

#include "shared/material/best_fit_rotation.hpp"

#include <gtest/gtest.h>

#include "tests/unit/material/deformation_samples.hpp"

namespace altfem {
namespace {

Eigen::Matrix3d rotation_of(const Eigen::Matrix3d& F) { return polar_rotation(F); }

TEST(PolarDecomposition, RotationVariantSvdReconstructsWithProperRotations) {
  std::mt19937 random(17);
  for (int sample = 0; sample < 100; ++sample) {
    const Eigen::Matrix3d F = 2.0 * test::random_matrix(random);
    const RotationVariantSvd svd = rotation_variant_svd(F);
    EXPECT_LE((svd.U * svd.sigma.asDiagonal() * svd.V.transpose() - F).norm(), 1e-14 * F.norm());
    EXPECT_NEAR(svd.U.determinant(), 1.0, 1e-14);
    EXPECT_NEAR(svd.V.determinant(), 1.0, 1e-14);
    EXPECT_LE((svd.U.transpose() * svd.U - Eigen::Matrix3d::Identity()).norm(), 1e-14);
    EXPECT_GE(svd.sigma(0), svd.sigma(1));
    EXPECT_GE(svd.sigma(1), std::abs(svd.sigma(2)));
    EXPECT_EQ(svd.sigma(2) < 0.0, F.determinant() < 0.0);
  }
}

TEST(PolarDecomposition, RotationDerivativeMatchesFiniteDifferences) {
  std::mt19937 random(19);
  const Eigen::Matrix3d R1 = test::random_rotation(random);
  const Eigen::Matrix3d R2 = test::random_rotation(random);
  std::vector<Eigen::Matrix3d> samples = test::random_deformations(random, 10, 0.7);
  samples.push_back(R1 * Eigen::Vector3d(1.5, 1.5, 1.5).asDiagonal() * R2.transpose());  // repeated
  samples.push_back(R1 * Eigen::Vector3d(1.5, 1.5 + 1e-9, 0.3).asDiagonal() * R2.transpose());
  samples.push_back(R1 * Eigen::Vector3d(1.2, 0.8, -0.3).asDiagonal() * R2.transpose());  // inverted
  for (const Eigen::Matrix3d& F : samples) {
    const Matrix9d dRdF = polar_rotation_derivative(rotation_variant_svd(F));
    const Matrix9d expected = test::finite_difference_jacobian(rotation_of, F, 1e-6);
    EXPECT_LE((dRdF - expected).norm(), 1e-7 * expected.norm()) << "F =\n" << F;
  }
}

// At F = I, dR[H] is the skew part of H.
TEST(PolarDecomposition, RotationDerivativeAtIdentityIsSkewPart) {
  const Matrix9d dRdF = polar_rotation_derivative(rotation_variant_svd(Eigen::Matrix3d::Identity()));
  std::mt19937 random(23);
  const Eigen::Matrix3d H = test::random_matrix(random);
  const Eigen::Matrix<double, 9, 1> dR = dRdF * H.reshaped();
  EXPECT_LE((dR.reshaped(3, 3) - 0.5 * (H - H.transpose())).norm(), 1e-15);
}

}  // namespace
}  // namespace altfem
