#pragma once
// Small-strain linear elasticity: ψ = μ ε:ε + λ/2 tr(ε)², ε = sym(F) − I.
// Not rotation invariant; its tangent is constant (is_linear() is true).
#include "shared/material/material.hpp"

namespace altfem {

class LinearElastic final : public Material {
public:
  LinearElastic(LameParameters lame, double density);

  /// The strain sym(G), without forming I + G.
  double energy_at(const Eigen::Matrix3d& G) const override;
  Eigen::Matrix3d pk1_at(const Eigen::Matrix3d& G) const override;
  void pk1_and_tangent_at(const Eigen::Matrix3d& G, Eigen::Matrix3d& P, Matrix9d& dPdF) const override;
  bool is_linear() const override { return true; }

private:
  Matrix9d tangent_;  // μ(δik δjl + δil δjk) + λ δij δkl, built once
};

}  // namespace altfem
