#pragma once
// First and second derivatives of J = det F, shared by the Neo-Hookean models.
// Written out rather than taken from Eigen: Eigen has no cofactor, and
// F.inverse().transpose() * J is undefined exactly where these stay valid (J = 0).
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross, determinant

#include "shared/material/material.hpp"

namespace altfem {

/// ∂J/∂F = cof F = J F⁻ᵀ (3 × 3), column by column [f1 × f2, f2 × f0, f0 × f1]
/// for the columns f0, f1, f2 of F.
inline Eigen::Matrix3d cofactor(const Eigen::Matrix3d& F) {
  Eigen::Matrix3d cof;
  cof.col(0) = F.col(1).cross(F.col(2));
  cof.col(1) = F.col(2).cross(F.col(0));
  cof.col(2) = F.col(0).cross(F.col(1));
  return cof;
}

/// ∂²J/∂F² (9 × 9, Matrix9d's vec ordering): Smith, De Goes & Kim 2018, "Stable
/// Neo-Hookean Flesh Simulation": the block matrix
/// [[0, −f̂2, f̂1], [f̂2, 0, −f̂0], [−f̂1, f̂0, 0]] of cross-product matrices f̂ = [f]×.
inline Matrix9d determinant_hessian(const Eigen::Matrix3d& F) {
  const auto cross_matrix = [](const Eigen::Vector3d& f) {
    Eigen::Matrix3d m;
    m << 0.0, -f.z(), f.y(), f.z(), 0.0, -f.x(), -f.y(), f.x(), 0.0;
    return m;
  };
  const Eigen::Matrix3d f0 = cross_matrix(F.col(0));
  const Eigen::Matrix3d f1 = cross_matrix(F.col(1));
  const Eigen::Matrix3d f2 = cross_matrix(F.col(2));
  Matrix9d H;
  H << Eigen::Matrix3d::Zero(), -f2, f1, f2, Eigen::Matrix3d::Zero(), -f0, -f1, f0, Eigen::Matrix3d::Zero();
  return H;
}

}  // namespace altfem
