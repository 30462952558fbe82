#include "shared/material/neo_hookean.hpp"

#include <cmath>
#include <limits>

#include "shared/material/determinant_derivatives.hpp"

namespace altfem {
namespace {
constexpr double infinity = std::numeric_limits<double>::infinity();

// det(I + G) − 1 = I₁ + I₂ + I₃ (the principal invariants of G) and I₂ + I₃, each a sum
// of small terms.
struct SmallStrain {
  double J_minus_one;
  double I2_plus_I3;
};

SmallStrain small_strain(const Eigen::Matrix3d& G) {
  const double I1 = G.trace();
  const double I2 = 0.5 * (I1 * I1 - (G * G).trace());
  const double I3 = G.determinant();
  return {I1 + I2 + I3, I2 + I3};
}

// x − log(1 + x) without cancellation for small |x| (its series), directly otherwise.
double x_minus_log1p(double x) {
  if (std::abs(x) > 1e-2) return x - std::log1p(x);
  double term = -x, sum = 0;  // Σ_{k≥2} (−1)^k x^k / k
  for (int k = 2; k <= 10; ++k) {
    term *= -x;
    sum += term / k;
  }
  return sum;
}
}  // namespace

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

// ψ = μ (tr G − log J) + μ/2 |G|² + λ/2 log² J, tr G − log J = (x − log1p x) − (I₂ + I₃)
// with x = J − 1 (|F|² − 3 = 2 tr G + |G|²).
double NeoHookean::energy_at(const Eigen::Matrix3d& G) const {
  const SmallStrain small = small_strain(G);
  if (!(small.J_minus_one > -1.0)) return infinity;
  const double log_J = std::log1p(small.J_minus_one);
  return infinite_unless_finite(lame().mu * (x_minus_log1p(small.J_minus_one) - small.I2_plus_I3) +
                                0.5 * lame().mu * G.squaredNorm() + 0.5 * lame().lambda * log_J * log_J);
}

// P = μ (F − F⁻ᵀ) + λ log J F⁻ᵀ with J F⁻ᵀ = cof F = (1 + tr G) I − Gᵀ + cof G, so
// F − F⁻ᵀ = G + (Gᵀ − cof G + (I₂ + I₃) I) / J.
Eigen::Matrix3d NeoHookean::pk1_at(const Eigen::Matrix3d& G) const {
  const SmallStrain small = small_strain(G);
  if (!(small.J_minus_one > -1.0)) return Eigen::Matrix3d::Constant(infinity);
  const double J = 1.0 + small.J_minus_one;
  Eigen::Matrix3d difference = G.transpose() - cofactor(G);
  difference.diagonal().array() += small.I2_plus_I3;
  const Eigen::Matrix3d F = G + Eigen::Matrix3d::Identity();
  Eigen::Matrix3d P =
      lame().mu * (G + difference / J) + (lame().lambda * std::log1p(small.J_minus_one) / J) * cofactor(F);
  infinite_unless_finite(P);
  return P;
}

void NeoHookean::pk1_and_tangent_at(const Eigen::Matrix3d& G, Eigen::Matrix3d& P, Matrix9d& dPdF) const {
  Eigen::Matrix3d unused;
  pk1_and_tangent(G + Eigen::Matrix3d::Identity(), unused, dPdF);
  P = pk1_at(G);
  if (!P.allFinite()) dPdF.setConstant(infinity);
}

}  // namespace altfem
