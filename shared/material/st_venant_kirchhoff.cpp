#include "shared/material/st_venant_kirchhoff.hpp"

namespace altfem {
namespace {

/// The Green strain E = (FᵀF − I)/2 = (G + Gᵀ + GᵀG)/2 of the displacement gradient G.
Eigen::Matrix3d green_strain(const Eigen::Matrix3d& G) { return 0.5 * (G + G.transpose() + G.transpose() * G); }

/// Second Piola–Kirchhoff stress S = 2μE + λ tr(E) I.
Eigen::Matrix3d second_piola_kirchhoff(const Eigen::Matrix3d& G, const LameParameters& lame) {
  const Eigen::Matrix3d E = green_strain(G);
  return 2.0 * lame.mu * E + lame.lambda * E.trace() * Eigen::Matrix3d::Identity();
}

}  // namespace

StVenantKirchhoff::StVenantKirchhoff(LameParameters lame, double density)
    : Material(MaterialModel::st_venant_kirchhoff, lame, density) {}

double StVenantKirchhoff::energy_at(const Eigen::Matrix3d& G) const {
  const Eigen::Matrix3d E = green_strain(G);
  const double trace = E.trace();
  return infinite_unless_finite(lame().mu * E.squaredNorm() + 0.5 * lame().lambda * trace * trace);
}

Eigen::Matrix3d StVenantKirchhoff::pk1_at(const Eigen::Matrix3d& G) const {
  Eigen::Matrix3d P = (G + Eigen::Matrix3d::Identity()) * second_piola_kirchhoff(G, lame());
  infinite_unless_finite(P);
  return P;
}

void StVenantKirchhoff::pk1_and_tangent_at(const Eigen::Matrix3d& G, Eigen::Matrix3d& P, Matrix9d& dPdF) const {
  const double mu = lame().mu;
  const double lambda = lame().lambda;
  const Eigen::Matrix3d F = G + Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d S = second_piola_kirchhoff(G, lame());
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
