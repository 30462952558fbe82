#pragma once
// One-dimensional Gauss rules on [-1,1]: the building blocks of the tensor (hex, quad)
// and collapsed (tet, triangle) product rules.
#include "shared/quadrature/quadrature_rule.hpp"

namespace altfem {

/// Gauss–Legendre rule with point_count >= 1 points on [-1,1] (points: #points × 1,
/// increasing); strength 2·point_count − 1, weights sum to 2.
/// Throws std::invalid_argument for point_count < 1.
QuadratureRule gauss_legendre(int point_count);

/// Gauss–Jacobi rule for the weight (1−x)^alpha (1+x)^beta on [-1,1], alpha, beta > −1:
/// Σ w_i f(x_i) = ∫ f(x) (1−x)^alpha (1+x)^beta dx exactly for deg f <= 2·point_count − 1.
/// points: #points × 1, increasing, strictly inside (−1,1).
/// Throws std::invalid_argument for point_count < 1 or alpha, beta <= −1.
QuadratureRule gauss_jacobi(int point_count, double alpha, double beta);

/// The fewest Gauss points per direction that integrate degree `strength` exactly:
/// ⌈(strength+1)/2⌉, and 1 for strength 0. Throws std::invalid_argument for strength < 0.
int gauss_point_count(int strength);

}  // namespace altfem
