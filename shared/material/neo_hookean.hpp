#pragma once
// Compressible Neo-Hookean (Bonet & Wood, "Nonlinear Continuum Mechanics for Finite Element Analysis"):
//   ψ = μ/2 (I_C − 3) − μ log J + λ/2 (log J)²,  I_C = tr(FᵀF), J = det F.
// Undefined for J ≤ 0: there energy() is +infinity (so a line search rejects the
// step) and pk1 / pk1_and_tangent are entirely +infinity (so the assembler's
// finiteness check names the element). Never NaN.
#include "shared/material/material.hpp"

namespace altfem {

class NeoHookean final : public Material {
public:
  NeoHookean(LameParameters lame, double density);

  /// Without cancelling O(1) terms: the invariants of G give J − 1, log J = log1p(J − 1)
  /// and F − F⁻ᵀ directly, so strains of 1e-11 (a 1 µm cube under gravity) keep their digits.
  double energy_at(const Eigen::Matrix3d& G) const override;
  Eigen::Matrix3d pk1_at(const Eigen::Matrix3d& G) const override;
  void pk1_and_tangent_at(const Eigen::Matrix3d& G, Eigen::Matrix3d& P, Matrix9d& dPdF) const override;

private:
  Eigen::Matrix3d pk1_with_cofactor(const Eigen::Matrix3d& G, double J_minus_one, double I2_plus_I3,
                                    Eigen::Matrix3d& cof_F) const;
};

}  // namespace altfem
