#include "shared/material/polar_decomposition.hpp"

#include <Eigen/LU>  // determinant
#include <Eigen/SVD>
#include <algorithm>
#include <limits>

namespace altfem {

RotationVariantSvd rotation_variant_svd(const Eigen::Matrix3d& F) {
  // Two-sided Jacobi: accurate small singular values, which the corotated
  // model's dR/dF divides by; no QR preconditioner is needed for a square matrix.
  const Eigen::JacobiSVD<Eigen::Matrix3d, Eigen::NoQRPreconditioner> svd(F, Eigen::ComputeFullU | Eigen::ComputeFullV);
  RotationVariantSvd result{svd.matrixU(), svd.singularValues(), svd.matrixV()};
  // Move any reflection into the smallest singular value (Irving et al. 2004).
  if (result.U.determinant() < 0.0) {
    result.U.col(2) *= -1.0;
    result.sigma(2) *= -1.0;
  }
  if (result.V.determinant() < 0.0) {
    result.V.col(2) *= -1.0;
    result.sigma(2) *= -1.0;
  }
  return result;
}

Matrix9d polar_rotation_derivative(const RotationVariantSvd& svd) {
  constexpr int pairs[3][2] = {{1, 2}, {0, 2}, {0, 1}};
  const double floor = std::numeric_limits<double>::epsilon() * std::max(svd.sigma(0), 1.0);
  Matrix9d dRdF = Matrix9d::Zero();
  for (const auto& pair : pairs) {
    const int a = pair[0];
    const int b = pair[1];
    // vec(T)vec(T)ᵀ · 2/(σa+σb) with T = twist/√2 equals vec(twist)vec(twist)ᵀ / (σa+σb).
    const Eigen::Matrix3d twist = svd.U.col(a) * svd.V.col(b).transpose() - svd.U.col(b) * svd.V.col(a).transpose();
    const Eigen::Map<const Eigen::Matrix<double, 9, 1>> vec_twist(twist.data());
    dRdF += (1.0 / std::max(svd.sigma(a) + svd.sigma(b), floor)) * vec_twist * vec_twist.transpose();
  }
  return dRdF;
}

}  // namespace altfem
