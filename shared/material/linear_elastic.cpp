#include "shared/material/linear_elastic.hpp"

namespace altfem {

LinearElastic::LinearElastic(LameParameters lame, double density) : Material(MaterialModel::linear, lame, density) {
  tangent_.setZero();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      tangent_(i + 3 * j, i + 3 * j) += lame.mu;
      tangent_(i + 3 * j, j + 3 * i) += lame.mu;
      tangent_(i + 3 * i, j + 3 * j) += lame.lambda;
    }
  }
}

double LinearElastic::energy_at(const Eigen::Matrix3d& G) const {
  const Eigen::Matrix3d strain = 0.5 * (G + G.transpose());
  const double trace = strain.trace();
  return infinite_unless_finite(lame().mu * strain.squaredNorm() + 0.5 * lame().lambda * trace * trace);
}

Eigen::Matrix3d LinearElastic::pk1_at(const Eigen::Matrix3d& G) const {
  const Eigen::Matrix3d strain = 0.5 * (G + G.transpose());
  Eigen::Matrix3d P = 2.0 * lame().mu * strain + lame().lambda * strain.trace() * Eigen::Matrix3d::Identity();
  infinite_unless_finite(P);
  return P;
}

void LinearElastic::pk1_and_tangent_at(const Eigen::Matrix3d& G, Eigen::Matrix3d& P, Matrix9d& dPdF) const {
  P = pk1_at(G);
  dPdF = tangent_;
  infinite_unless_finite(P, dPdF);
}

}  // namespace altfem
