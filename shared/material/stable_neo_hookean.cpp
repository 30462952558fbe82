#include "shared/material/stable_neo_hookean.hpp"

#include <cmath>

#include "shared/material/determinant_derivatives.hpp"

namespace altfem {

StableNeoHookean::StableNeoHookean(LameParameters lame, double density)
    : Material(MaterialModel::stable_neo_hookean, lame, density),
      lambda_(lame.lambda + 5.0 / 6.0 * lame.mu),
      mu_(4.0 / 3.0 * lame.mu),
      alpha_(1.0 + 0.75 * mu_ / lambda_),
      rest_energy_(0.5 * lambda_ * (1.0 - alpha_) * (1.0 - alpha_) - 0.5 * mu_ * std::log(4.0)) {}

double StableNeoHookean::energy(const Eigen::Matrix3d& F) const {
  const double I_C = F.squaredNorm();
  const double volume_change = F.determinant() - alpha_;
  return infinite_unless_finite(0.5 * mu_ * (I_C - 3.0) + 0.5 * lambda_ * volume_change * volume_change -
                                0.5 * mu_ * std::log1p(I_C) - rest_energy_);
}

// P = μ'(1 − 1/(I_C + 1)) F + λ'(J − α) cof F.
Eigen::Matrix3d StableNeoHookean::pk1(const Eigen::Matrix3d& F) const {
  const double I_C = F.squaredNorm();
  Eigen::Matrix3d P = (mu_ * (1.0 - 1.0 / (I_C + 1.0))) * F + (lambda_ * (F.determinant() - alpha_)) * cofactor(F);
  infinite_unless_finite(P);
  return P;
}

// dP/dF = μ'(1 − 1/(I_C+1)) I + 2μ'/(I_C+1)² F ⊗ F + λ' cof ⊗ cof + λ'(J − α) ∂²J/∂F².
void StableNeoHookean::pk1_and_tangent(const Eigen::Matrix3d& F, Eigen::Matrix3d& P, Matrix9d& dPdF) const {
  const double I_C = F.squaredNorm();
  const double inverse_I_C_plus_1 = 1.0 / (I_C + 1.0);
  const double identity_scale = mu_ * (1.0 - inverse_I_C_plus_1);
  const double cofactor_scale = lambda_ * (F.determinant() - alpha_);
  const Eigen::Matrix3d cof = cofactor(F);
  const Eigen::Map<const Eigen::Matrix<double, 9, 1>> vec_F(F.data());
  const Eigen::Map<const Eigen::Matrix<double, 9, 1>> vec_cof(cof.data());
  P = identity_scale * F + cofactor_scale * cof;
  dPdF = (2.0 * mu_ * inverse_I_C_plus_1 * inverse_I_C_plus_1) * vec_F * vec_F.transpose() +
         lambda_ * vec_cof * vec_cof.transpose() + cofactor_scale * determinant_hessian(F);
  dPdF.diagonal().array() += identity_scale;
  infinite_unless_finite(P, dPdF);
}

}  // namespace altfem
