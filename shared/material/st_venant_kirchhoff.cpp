#include "shared/material/st_venant_kirchhoff.hpp"

namespace altfem {
namespace {

/// Second Piola–Kirchhoff stress S = 2μE + λ tr(E) I.
Eigen::Matrix3d second_piola_kirchhoff(const Eigen::Matrix3d& F, const LameParameters& lame) {
  const Eigen::Matrix3d E = 0.5 * (F.transpose() * F - Eigen::Matrix3d::Identity());
  return 2.0 * lame.mu * E + lame.lambda * E.trace() * Eigen::Matrix3d::Identity();
}

}  // namespace

StVenantKirchhoff::StVenantKirchhoff(LameParameters lame, double density)
    : Material(MaterialModel::st_venant_kirchhoff, lame, density) {}

double StVenantKirchhoff::energy(const Eigen::Matrix3d& F) const {
  const Eigen::Matrix3d E = 0.5 * (F.transpose() * F - Eigen::Matrix3d::Identity());
  const double trace = E.trace();
  return infinite_unless_finite(lame().mu * E.squaredNorm() + 0.5 * lame().lambda * trace * trace);
}

Eigen::Matrix3d StVenantKirchhoff::pk1(const Eigen::Matrix3d& F) const {
  Eigen::Matrix3d P = F * second_piola_kirchhoff(F, lame());
  infinite_unless_finite(P);
  return P;
}

void StVenantKirchhoff::pk1_and_tangent(const Eigen::Matrix3d& F, Eigen::Matrix3d& P, Matrix9d& dPdF) const {
  const double mu = lame().mu;
  const double lambda = lame().lambda;
  const Eigen::Matrix3d S = second_piola_kirchhoff(F, lame());
  const Eigen::Matrix3d FFt = F * F.transpose();
  P = F * S;
  // ∂P_ij/∂F_kl = δik S_lj + μ F_il F_kj + μ (FFᵀ)_ik δjl + λ F_ij F_kl; the 3 × 3
  // block (j, l) holds rows i and columns k.
  for (int j = 0; j < 3; ++j) {
    for (int l = 0; l < 3; ++l) {
      Eigen::Matrix3d block = S(l, j) * Eigen::Matrix3d::Identity() + mu * F.col(l) * F.col(j).transpose() +
                              lambda * F.col(j) * F.col(l).transpose();
      if (j == l) block += mu * FFt;
      dPdF.block<3, 3>(3 * j, 3 * l) = block;
    }
  }
  infinite_unless_finite(P, dPdF);
}

}  // namespace altfem
