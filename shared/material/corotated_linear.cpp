#include "shared/material/corotated_linear.hpp"

#include "shared/material/polar_decomposition.hpp"

namespace altfem {

CorotatedLinear::CorotatedLinear(LameParameters lame, double density)
    : Material(MaterialModel::corotated_linear, lame, density) {}

// In singular values: ψ = μ Σ(σi − 1)² + λ/2 (Σσi − 3)².
double CorotatedLinear::energy_at(const Eigen::Matrix3d& G) const {
  const Eigen::Vector3d sigma = rotation_variant_svd(G + Eigen::Matrix3d::Identity()).sigma;
  const double trace = sigma.sum() - 3.0;
  return infinite_unless_finite(lame().mu * (sigma.array() - 1.0).square().sum() + 0.5 * lame().lambda * trace * trace);
}

// P = 2μ(F − R) + λ tr(S − I) R; the terms in dR vanish because RᵀdR is skew
// and S symmetric.
Eigen::Matrix3d CorotatedLinear::pk1_at(const Eigen::Matrix3d& G) const {
  const Eigen::Matrix3d F = G + Eigen::Matrix3d::Identity();
  const RotationVariantSvd svd = rotation_variant_svd(F);
  const Eigen::Matrix3d R = svd.U * svd.V.transpose();
  Eigen::Matrix3d P = 2.0 * lame().mu * (F - R) + (lame().lambda * (svd.sigma.sum() - 3.0)) * R;
  infinite_unless_finite(P);
  return P;
}

// dP/dF = 2μ I + λ vec(R) vec(R)ᵀ + (λ tr(S − I) − 2μ) ∂R/∂F, using ∂tr(S)/∂F = R.
void CorotatedLinear::pk1_and_tangent_at(const Eigen::Matrix3d& G, Eigen::Matrix3d& P, Matrix9d& dPdF) const {
  const Eigen::Matrix3d F = G + Eigen::Matrix3d::Identity();
  const double mu = lame().mu;
  const double lambda = lame().lambda;
  const RotationVariantSvd svd = rotation_variant_svd(F);
  const Eigen::Matrix3d R = svd.U * svd.V.transpose();
  const double volumetric = lambda * (svd.sigma.sum() - 3.0);
  const Eigen::Map<const Eigen::Matrix<double, 9, 1>> vec_R(R.data());
  P = 2.0 * mu * (F - R) + volumetric * R;
  dPdF = lambda * vec_R * vec_R.transpose() + (volumetric - 2.0 * mu) * polar_rotation_derivative(svd);
  dPdF.diagonal().array() += 2.0 * mu;
  infinite_unless_finite(P, dPdF);
}

}  // namespace altfem
