#pragma once
// Invariants of the displacement gradient G = F − I computed without cancelling O(1)
// terms, for the hyperelastic models' forms in G (Material::energy_at and friends): a
// 1 µm body under gravity has |G| ~ 1e-13, where anything formed from F = I + G first
// keeps only a few digits (issue #35).
#include <Eigen/Core>
#include <cmath>

namespace altfem {

/// det(I + G) − 1 = I₁ + I₂ + I₃ (the principal invariants of G) and I₂ + I₃, each a sum
/// of small terms.
struct SmallStrain {
  double J_minus_one;
  double I2_plus_I3;
};

inline SmallStrain small_strain(const Eigen::Matrix3d& G) {
  const double I1 = G.trace();
  const double I2 = 0.5 * (I1 * I1 - (G * G).trace());
  const double I3 = G.determinant();
  return {I1 + I2 + I3, I2 + I3};
}

/// x − log(1 + x) without cancellation for small |x| (its series), directly otherwise.
inline double x_minus_log1p(double x) {
  if (std::abs(x) > 1e-2) return x - std::log1p(x);
  double term = -x, sum = 0;  // Σ_{k≥2} (−1)^k x^k / k
  for (int k = 2; k <= 10; ++k) {
    term *= -x;
    sum += term / k;
  }
  return sum;
}

}  // namespace altfem
