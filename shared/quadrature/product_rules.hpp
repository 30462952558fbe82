#pragma once
// Product rules of any strength, built from one-dimensional Gauss rules: the fallback
// when no shipped Witherden–Vincent table is strong enough (see reference_rules.hpp),
// and a reference to check those tables against. All weights are positive and all
// points strictly inside the domain. Throw std::invalid_argument for strength < 0;
// strength 0 gives the one-point rule (strength 1).
#include "shared/quadrature/quadrature_rule.hpp"

namespace altfem {

/// Tensor Gauss–Legendre rule on [-1,1]²; points: n² × 2 with n = gauss_point_count(strength).
QuadratureRule tensor_quad_rule(int strength);

/// Tensor Gauss–Legendre rule on [-1,1]³; points: n³ × 3.
QuadratureRule tensor_hex_rule(int strength);

/// Collapsed (Duffy / Stroud conical product) rule on the unit triangle {x,y >= 0,
/// x+y <= 1}; points: n² × 2, weights sum to 1/2.
QuadratureRule collapsed_triangle_rule(int strength);

/// Collapsed (Duffy / Stroud conical product) rule on the unit tetrahedron
/// {x,y,z >= 0, x+y+z <= 1}; points: n³ × 3, weights sum to 1/6.
QuadratureRule collapsed_tet_rule(int strength);

}  // namespace altfem
