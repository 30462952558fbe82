#include "shared/material/neo_hookean.hpp"

#include <cmath>
#include <limits>

#include "shared/material/determinant_derivatives.hpp"
#include "shared/material/small_strain.hpp"

namespace altfem {
namespace {
constexpr double infinity = std::numeric_limits<double>::infinity();
}  // namespace

NeoHookean::NeoHookean(LameParameters lame, double density) : Material(MaterialModel::neo_hookean, lame, density) {}

// ψ = μ (tr G − log J) + μ/2 |G|² + λ/2 log² J, tr G − log J = (x − log1p x) − (I₂ + I₃)
// with x = J − 1 (|F|² − 3 = 2 tr G + |G|²).
double NeoHookean::energy_at(const Eigen::Matrix3d& G) const {
  const SmallStrain small = small_strain(G);
  if (!(small.J_minus_one > -1.0)) return infinity;
  const double log_J = std::log1p(small.J_minus_one);
  return infinite_unless_finite(lame().mu * (x_minus_log1p(small.J_minus_one) - small.I2_plus_I3) +
                                0.5 * lame().mu * G.squaredNorm() + 0.5 * lame().lambda * log_J * log_J);
}

// P = μ (F − F⁻ᵀ) + λ log J F⁻ᵀ. With cof F = J F⁻ᵀ = (1 + tr G) I − Gᵀ + cof G and
// D = Gᵀ − cof G + (I₂ + I₃) I: cof F = J I − D and F − F⁻ᵀ = G + D / J, both without
// cancelling O(1) terms. `cof_F` receives cof F.
Eigen::Matrix3d NeoHookean::pk1_with_cofactor(const Eigen::Matrix3d& G, double J_minus_one, double I2_plus_I3,
                                              Eigen::Matrix3d& cof_F) const {
  const double J = 1.0 + J_minus_one;
  Eigen::Matrix3d D = G.transpose() - cofactor(G);
  D.diagonal().array() += I2_plus_I3;
  cof_F = -D;
  cof_F.diagonal().array() += J;
  return lame().mu * (G + D / J) + (lame().lambda * std::log1p(J_minus_one) / J) * cof_F;
}

Eigen::Matrix3d NeoHookean::pk1_at(const Eigen::Matrix3d& G) const {
  const SmallStrain small = small_strain(G);
  if (!(small.J_minus_one > -1.0)) return Eigen::Matrix3d::Constant(infinity);
  Eigen::Matrix3d cof_F;
  Eigen::Matrix3d P = pk1_with_cofactor(G, small.J_minus_one, small.I2_plus_I3, cof_F);
  infinite_unless_finite(P);
  return P;
}

// dP/dF = μ I + (λ(1 − log J) + μ)/J² cof ⊗ cof + (λ log J − μ)/J ∂²J/∂F².
void NeoHookean::pk1_and_tangent_at(const Eigen::Matrix3d& G, Eigen::Matrix3d& P, Matrix9d& dPdF) const {
  const SmallStrain small = small_strain(G);
  if (!(small.J_minus_one > -1.0)) {
    P.setConstant(infinity);
    dPdF.setConstant(infinity);
    return;
  }
  const double mu = lame().mu;
  const double lambda = lame().lambda;
  const double J = 1.0 + small.J_minus_one;
  const double log_J = std::log1p(small.J_minus_one);
  Eigen::Matrix3d cof;
  P = pk1_with_cofactor(G, small.J_minus_one, small.I2_plus_I3, cof);
  const Eigen::Map<const Eigen::Matrix<double, 9, 1>> vec_cof(cof.data());
  dPdF = ((lambda * (1.0 - log_J) + mu) / (J * J)) * vec_cof * vec_cof.transpose() +
         ((lambda * log_J - mu) / J) * determinant_hessian(G + Eigen::Matrix3d::Identity());
  dPdF.diagonal().array() += mu;
  infinite_unless_finite(P, dPdF);
}

}  // namespace altfem
