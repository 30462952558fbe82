#pragma once
// Checks shared by the quadrature tests: exact monomial integrals on boxes [-1,1]^d and
// unit simplices, and the "positive weights, strictly interior points" property.
#include "shared/quadrature/quadrature_rule.hpp"

#include <gtest/gtest.h>

#include <string>

namespace altfem::testing {

enum class Shape { box, simplex };  // [-1,1]^d, or {x_i >= 0, Σ x_i <= 1}; d = points.cols()

/// Largest relative error |Q(f) − ∫f| / max(|∫f|, ∫|f|) (docs/conventions.md) over the
/// monomials f = x^a y^b z^c of total degree <= degree; `worst` names the monomial.
double largest_monomial_error(const QuadratureRule& rule, Shape shape, int degree, std::string* worst = nullptr);

/// Success if every weight is > 0 and every point strictly inside the domain.
::testing::AssertionResult positive_and_interior(const QuadratureRule& rule, Shape shape);

/// Success if every weight is > 0 and every point inside the domain or on its boundary
/// (to 1e-15).
::testing::AssertionResult positive_and_in_closure(const QuadratureRule& rule, Shape shape);

/// Success if largest_monomial_error(rule, shape, degree) <= tolerance.
::testing::AssertionResult exact_to_degree(const QuadratureRule& rule, Shape shape, int degree,
                                           double tolerance = 1e-13);

}  // namespace altfem::testing
