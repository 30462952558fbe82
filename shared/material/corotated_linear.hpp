#pragma once
// Corotated linear elasticity (McAdams et al. 2011, "Efficient elasticity for
// character skinning with contact and collisions"; Stomakhin et al. 2012):
//   ψ = μ ‖F − R‖² + λ/2 tr(RᵀF − I)²,  F = R S (polar decomposition),
// i.e. linear elasticity in the rotated frame. R comes from the rotation-variant
// SVD, so ψ, P and dP/dF are defined (and finite) for inverted F too.
#include "shared/material/material.hpp"

namespace altfem {

class CorotatedLinear final : public Material {
public:
  CorotatedLinear(LameParameters lame, double density);

  /// From F = I + G: the polar decomposition needs F, and R − I would keep only
  /// round-off's digits of a tiny G anyway.
  double energy_at(const Eigen::Matrix3d& G) const override;
  Eigen::Matrix3d pk1_at(const Eigen::Matrix3d& G) const override;
  void pk1_and_tangent_at(const Eigen::Matrix3d& G, Eigen::Matrix3d& P, Matrix9d& dPdF) const override;
};

}  // namespace altfem
