#include "shared/material/neo_hookean.hpp"

#include <cmath>
#include <limits>

#include "shared/material/determinant_derivatives.hpp"

namespace altfem {
namespace {
constexpr double infinity = std::numeric_limits<double>::infinity();
}

NeoHookean::NeoHookean(LameParameters lame, double density) : Material(MaterialModel::neo_hookean, lame, density) {}

double NeoHookean::energy(const Eigen::Matrix3d& F) const {
  const double J = F.determinant();
  if (!(J > 0.0)) return infinity;
  const double log_J = std::log(J);
  return infinite_unless_finite(0.5 * lame().mu * (F.squaredNorm() - 3.0) - lame().mu * log_J +
                                0.5 * lame().lambda * log_J * log_J);
}

// P = μF + (λ log J − μ) F⁻ᵀ, with F⁻ᵀ = cof F / J.
Eigen::Matrix3d NeoHookean::pk1(const Eigen::Matrix3d& F) const {
  const double J = F.determinant();
  if (!(J > 0.0)) return Eigen::Matrix3d::Constant(infinity);
  Eigen::Matrix3d P = lame().mu * F + ((lame().lambda * std::log(J) - lame().mu) / J) * cofactor(F);
  infinite_unless_finite(P);
  return P;
}

// dP/dF = μ I + (λ(1 − log J) + μ)/J² cof ⊗ cof + (λ log J − μ)/J ∂²J/∂F².
void NeoHookean::pk1_and_tangent(const Eigen::Matrix3d& F, Eigen::Matrix3d& P, Matrix9d& dPdF) const {
  const double J = F.determinant();
  if (!(J > 0.0)) {
    P.setConstant(infinity);
    dPdF.setConstant(infinity);
    return;
  }
  const double mu = lame().mu;
  const double lambda = lame().lambda;
  const double log_J = std::log(J);
  const double stress_scale = (lambda * log_J - mu) / J;
  const Eigen::Matrix3d cof = cofactor(F);
  const Eigen::Map<const Eigen::Matrix<double, 9, 1>> vec_cof(cof.data());
  P = mu * F + stress_scale * cof;
  dPdF =
      ((lambda * (1.0 - log_J) + mu) / (J * J)) * vec_cof * vec_cof.transpose() + stress_scale * determinant_hessian(F);
  dPdF.diagonal().array() += mu;
  infinite_unless_finite(P, dPdF);
}

}  // namespace altfem
