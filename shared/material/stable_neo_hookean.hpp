#pragma once
// Stable Neo-Hookean, Smith, De Goes & Kim 2018, "Stable Neo-Hookean Flesh
// Simulation", ACM TOG 37(2), the energy with the log(I_C + 1) term:
//   ψ = μ'/2 (I_C − 3) + λ'/2 (J − α)² − μ'/2 log(I_C + 1),  α = 1 + 3μ'/(4λ'),
// shifted by a constant so that ψ(I) = 0. Defined and finite for every F,
// including inverted and singular ones.
//
// α: with the log term the rest state is stress free only for
// α = 1 + μ'/λ' − μ'/(4λ') = 1 + 3μ'/(4λ') (P(I) = μ' − μ'/4 + λ'(1 − α) = 0);
// α = 1 + μ'/λ' belongs to the paper's energy *without* the log term (its eq. 14).
// Lamé mapping (the paper's "Lamé reparametrization"): linearising P at F = I gives
// 2·(3μ'/4) ε + (λ' − 5μ'/8) tr ε I, so matching linear elasticity's (λ, μ) needs
//   μ' = 4μ/3,  λ' = λ + 5μ/6;
// the constructor takes the small-strain (λ, μ) and applies this mapping.
#include "shared/material/material.hpp"

namespace altfem {

class StableNeoHookean final : public Material {
public:
  /// `lame`: the small-strain Lamé parameters (as from lame_parameters(E, ν)).
  StableNeoHookean(LameParameters lame, double density);

  /// Without cancelling O(μ) terms where |G| is tiny (stable_neo_hookean.cpp).
  double energy_at(const Eigen::Matrix3d& G) const override;
  Eigen::Matrix3d pk1_at(const Eigen::Matrix3d& G) const override;
  void pk1_and_tangent_at(const Eigen::Matrix3d& G, Eigen::Matrix3d& P, Matrix9d& dPdF) const override;

  /// The reparametrised (λ', μ') that appear in ψ.
  LameParameters energy_lame() const { return {lambda_, mu_}; }

private:
  double lambda_;
  double mu_;
  double alpha_;

  Eigen::Matrix3d pk1_with_cofactor(const Eigen::Matrix3d& G, Eigen::Matrix3d& cof_F) const;
};

}  // namespace altfem
