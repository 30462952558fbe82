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

  double energy(const Eigen::Matrix3d& F) const override;
  Eigen::Matrix3d pk1(const Eigen::Matrix3d& F) const override;
  void pk1_and_tangent(const Eigen::Matrix3d& F, Eigen::Matrix3d& P, Matrix9d& dPdF) const override;
};

}  // namespace altfem
