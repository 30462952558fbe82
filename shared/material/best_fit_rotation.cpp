#include "shared/material/best_fit_rotation.hpp"

#include <Eigen/LU>

#include "shared/material/polar_decomposition.hpp"

namespace altfem {

Eigen::Matrix3d polar_rotation(const Eigen::Matrix3d& F) {
  const RotationVariantSvd svd = rotation_variant_svd(F);
  return svd.U * svd.V.transpose();
}

Eigen::Matrix3d best_fit_rotation(const Eigen::MatrixXd& rest, const Eigen::MatrixXd& deformed,
                                  const Eigen::VectorXd& weights) {
  const double total = weights.sum();
  const Eigen::RowVector3d rest_centroid = weights.transpose() * rest / total;
  const Eigen::RowVector3d deformed_centroid = weights.transpose() * deformed / total;
  const Eigen::MatrixXd p = rest.rowwise() - rest_centroid;
  const Eigen::MatrixXd q = deformed.rowwise() - deformed_centroid;
  // Müller et al. 2005, eq. (7): A = A_pq A_qq⁻¹ (their names; here A_pp for Σ w p̂ p̂ᵀ).
  const Eigen::Matrix3d moment_qp = q.transpose() * weights.asDiagonal() * p;
  const Eigen::Matrix3d moment_pp = p.transpose() * weights.asDiagonal() * p;
  return polar_rotation(moment_qp * moment_pp.inverse());
}

}  // namespace altfem
