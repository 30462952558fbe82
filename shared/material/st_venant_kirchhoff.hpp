#pragma once
// St. Venant–Kirchhoff: ψ = μ E:E + λ/2 tr(E)², E = (FᵀF − I)/2 (Green strain).
// Rotation invariant but softens and collapses under strong compression
// (the volumetric stress vanishes again as J → 0), so inversion is not resisted.
#include "shared/material/material.hpp"

namespace altfem {

class StVenantKirchhoff final : public Material {
public:
  StVenantKirchhoff(LameParameters lame, double density);

  /// E = (G + Gᵀ + GᵀG)/2, exact where |G| is tiny, instead of FᵀF − I cancelling O(1) terms.
  double energy_at(const Eigen::Matrix3d& G) const override;
  Eigen::Matrix3d pk1_at(const Eigen::Matrix3d& G) const override;
  void pk1_and_tangent_at(const Eigen::Matrix3d& G, Eigen::Matrix3d& P, Matrix9d& dPdF) const override;
};

}  // namespace altfem
