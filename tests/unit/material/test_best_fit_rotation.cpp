// The rotation of a least-squares affine fit (Kaufmann et al. 2009 §6.1): exact for a
// rotated, stretched and translated point set, proper for a reflected one.
#include "shared/material/best_fit_rotation.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

namespace altfem {
namespace {

TEST(BestFitRotation, RecoversTheRotationOfAnAffineMapWithSymmetricStretch) {
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(1.2, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  Eigen::Matrix3d stretch;  // symmetric positive definite: F = R S
  stretch << 1.3, 0.1, -0.2, 0.1, 0.8, 0.05, -0.2, 0.05, 1.1;
  const Eigen::MatrixXd rest = Eigen::MatrixXd::Random(9, 3);
  const Eigen::MatrixXd deformed = (rest * (rotation * stretch).transpose()).rowwise() + Eigen::RowVector3d(4, -1, 2);
  const Eigen::VectorXd weights = Eigen::VectorXd::LinSpaced(9, 0.5, 2.0);
  EXPECT_LE((best_fit_rotation(rest, deformed, weights) - rotation).norm(), 1e-12);
  EXPECT_LE((polar_rotation(rotation * stretch) - rotation).norm(), 1e-12);
}

TEST(BestFitRotation, AReflectionStillGivesAProperRotation) {
  const Eigen::MatrixXd rest = Eigen::MatrixXd::Random(6, 3);
  Eigen::MatrixXd deformed = rest;
  deformed.col(2) *= -1;  // a mirror image: det A = −1
  const Eigen::Matrix3d rotation = best_fit_rotation(rest, deformed, Eigen::VectorXd::Ones(6));
  EXPECT_NEAR(rotation.determinant(), 1.0, 1e-12);
  EXPECT_LE((rotation.transpose() * rotation - Eigen::Matrix3d::Identity()).norm(), 1e-12);
}

}  // namespace
}  // namespace altfem
