#pragma once
// The rule to use on a reference domain for a given strength (docs/conventions.md, "Numerical conventions"):
// the smallest shipped Witherden–Vincent rule of strength >= the request whose points are
// all strictly inside the domain (on boxes: unless the tensor Gauss–Legendre rule has
// fewer points), else the product rule (collapsed Gauss–Jacobi on simplices, tensor
// Gauss–Legendre on boxes). Either way the weights are positive and the points strictly
// inside the domain.
// Strength 0 is served like strength 1; a negative strength throws std::invalid_argument;
// an unreadable shipped table throws InputError.
#include "shared/quadrature/product_rules.hpp"
#include "shared/quadrature/quadrature_rule.hpp"
#include "shared/quadrature/reference_domain.hpp"

namespace altfem {

/// On `domain` as defined in reference_domain.hpp; points: #points × reference_dimension(domain).
QuadratureRule reference_rule(ReferenceDomain domain, int strength);

QuadratureRule hex_rule(int strength);       ///< [-1,1]³, weights sum to 8
QuadratureRule quad_rule(int strength);      ///< [-1,1]², weights sum to 4
QuadratureRule tet_rule(int strength);       ///< unit tet {x,y,z >= 0, x+y+z <= 1}, weights sum to 1/6
QuadratureRule triangle_rule(int strength);  ///< unit triangle {x,y >= 0, x+y <= 1}, weights sum to 1/2

}  // namespace altfem
