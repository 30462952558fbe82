#pragma once
// Deformation gradients shared by the material tests, and finite differences.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <functional>
#include <random>
#include <vector>

#include "shared/material/material.hpp"

namespace altfem::test {

inline Eigen::Matrix3d random_rotation(std::mt19937& random) {
  std::normal_distribution<double> normal;
  Eigen::Quaterniond q(normal(random), normal(random), normal(random), normal(random));
  return q.normalized().toRotationMatrix();
}

inline Eigen::Matrix3d random_matrix(std::mt19937& random) {
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::Matrix3d m;
  for (double& entry : m.reshaped()) entry = uniform(random);
  return m;
}

/// `count` random F = I + scale·G (G entries uniform in [−1, 1]) with det F > 0.2.
inline std::vector<Eigen::Matrix3d> random_deformations(std::mt19937& random, int count, double scale) {
  std::vector<Eigen::Matrix3d> result;
  while (static_cast<int>(result.size()) < count) {
    const Eigen::Matrix3d F = Eigen::Matrix3d::Identity() + scale * random_matrix(random);
    if (F.determinant() > 0.2) result.push_back(F);
  }
  return result;
}

/// Central difference of a scalar function of F: a 3 × 3 gradient.
inline Eigen::Matrix3d finite_difference_gradient(const std::function<double(const Eigen::Matrix3d&)>& f,
                                                  const Eigen::Matrix3d& F, double step) {
  Eigen::Matrix3d gradient;
  for (int k = 0; k < 9; ++k) {
    Eigen::Matrix3d plus = F, minus = F;
    plus.reshaped()(k) += step;
    minus.reshaped()(k) -= step;
    gradient.reshaped()(k) = (f(plus) - f(minus)) / (2.0 * step);
  }
  return gradient;
}

/// Central difference of a matrix function of F: column k + 3l is ∂vec(G)/∂F_kl.
inline Matrix9d finite_difference_jacobian(const std::function<Eigen::Matrix3d(const Eigen::Matrix3d&)>& g,
                                           const Eigen::Matrix3d& F, double step) {
  Matrix9d jacobian;
  for (int k = 0; k < 9; ++k) {
    Eigen::Matrix3d plus = F, minus = F;
    plus.reshaped()(k) += step;
    minus.reshaped()(k) -= step;
    jacobian.col(k) = ((g(plus) - g(minus)) / (2.0 * step)).reshaped();
  }
  return jacobian;
}

}  // namespace altfem::test
