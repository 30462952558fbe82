#include "shared/material/stable_neo_hookean.hpp"

#include <cmath>

#include "shared/material/determinant_derivatives.hpp"
#include "shared/material/small_strain.hpp"

namespace altfem {

StableNeoHookean::StableNeoHookean(LameParameters lame, double density)
    : Material(MaterialModel::stable_neo_hookean, lame, density),
      lambda_(lame.lambda + 5.0 / 6.0 * lame.mu),
      mu_(4.0 / 3.0 * lame.mu),
      alpha_(1.0 + 0.75 * mu_ / lambda_) {}

// With d_I = I_C − 3 = 2 tr G + |G|², d_J = J − 1 and a = α − 1 = 3μ'/(4λ'), ψ − ψ(I) =
// μ'/2 d_I + λ'/2 (d_J² − 2a d_J) − μ'/2 log(1 + d_I/4), whose first-order terms cancel
// (the rest state is stress free). Grouped so that none does:
//   ψ = 3μ'/4 (d_I/2 − d_J) + μ'/2 (x − log1p x) + λ'/2 d_J²,   x = d_I/4,
// with d_I/2 − d_J = |G|²/2 − (I₂ + I₃) a second-order sum.
double StableNeoHookean::energy_at(const Eigen::Matrix3d& G) const {
  const SmallStrain small = small_strain(G);
  const double squared_norm = G.squaredNorm();
  const double x = 0.25 * (2.0 * G.trace() + squared_norm);
  return infinite_unless_finite(0.75 * mu_ * (0.5 * squared_norm - small.I2_plus_I3) + 0.5 * mu_ * x_minus_log1p(x) +
                                0.5 * lambda_ * small.J_minus_one * small.J_minus_one);
}

// P = μ'(1 − 1/(I_C + 1)) F + λ'(J − α) cof F, whose O(μ') parts cancel at F = I. With
// cof F = J I − D, D = Gᵀ − cof G + (I₂ + I₃) I (as Neo-Hookean's), and
// 1 − 1/(I_C + 1) = 3/4 + s, s = d_I / (4 (4 + d_I)):
//   P = 3μ'/4 (G + D − d_J I) + μ' s F + λ' d_J cof F,
// each term O(G). `cof_F` receives cof F.
Eigen::Matrix3d StableNeoHookean::pk1_with_cofactor(const Eigen::Matrix3d& G, Eigen::Matrix3d& cof_F) const {
  const SmallStrain small = small_strain(G);
  const double d_I = 2.0 * G.trace() + G.squaredNorm();
  const double s = d_I / (4.0 * (4.0 + d_I));
  Eigen::Matrix3d D = G.transpose() - cofactor(G);
  D.diagonal().array() += small.I2_plus_I3;
  cof_F = -D;
  cof_F.diagonal().array() += 1.0 + small.J_minus_one;
  Eigen::Matrix3d P =
      0.75 * mu_ * (G + D) + (mu_ * s) * (G + Eigen::Matrix3d::Identity()) + (lambda_ * small.J_minus_one) * cof_F;
  P.diagonal().array() -= 0.75 * mu_ * small.J_minus_one;
  return P;
}

Eigen::Matrix3d StableNeoHookean::pk1_at(const Eigen::Matrix3d& G) const {
  Eigen::Matrix3d cof_F;
  Eigen::Matrix3d P = pk1_with_cofactor(G, cof_F);
  infinite_unless_finite(P);
  return P;
}

// dP/dF = μ'(1 − 1/(I_C+1)) I + 2μ'/(I_C+1)² F ⊗ F + λ' cof ⊗ cof + λ'(J − α) ∂²J/∂F²:
// O(μ') terms, no cancellation to avoid.
void StableNeoHookean::pk1_and_tangent_at(const Eigen::Matrix3d& G, Eigen::Matrix3d& P, Matrix9d& dPdF) const {
  const Eigen::Matrix3d F = G + Eigen::Matrix3d::Identity();
  const double I_C = F.squaredNorm();
  const double inverse_I_C_plus_1 = 1.0 / (I_C + 1.0);
  Eigen::Matrix3d cof;
  P = pk1_with_cofactor(G, cof);
  const Eigen::Map<const Eigen::Matrix<double, 9, 1>> vec_F(F.data());
  const Eigen::Map<const Eigen::Matrix<double, 9, 1>> vec_cof(cof.data());
  dPdF = (2.0 * mu_ * inverse_I_C_plus_1 * inverse_I_C_plus_1) * vec_F * vec_F.transpose() +
         lambda_ * vec_cof * vec_cof.transpose() + (lambda_ * (F.determinant() - alpha_)) * determinant_hessian(F);
  dPdF.diagonal().array() += mu_ * (1.0 - inverse_I_C_plus_1);
  infinite_unless_finite(P, dPdF);
}

}  // namespace altfem
