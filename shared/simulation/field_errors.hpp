#pragma once
// The errors of a method's displacement against an exact solution u(X, t) given as an
// expression (docs/conventions.md, "Metrics"): ‖u_h − u‖_L2 and the H1 seminorm
// ‖∇u_h − ∇u‖_L2 over the method's domain, by its own quadrature.
#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "shared/scene/vector_expression.hpp"
#include "shared/simulation/field_quadrature.hpp"

namespace altfem {

struct FieldErrors {
  double l2 = 0;                 ///< ‖u_h − u‖_L2 (m·m^{3/2})
  double h1_seminorm = 0;        ///< ‖∇u_h − ∇u‖_L2
  double exact_l2 = 0;           ///< ‖u‖_L2
  double exact_h1_seminorm = 0;  ///< ‖∇u‖_L2
  int strength = 0;              ///< of the rule used
};

/// Errors of the coefficients u (#dofs, basis function a carrying 3a..3a+2) against
/// `exact` at time t. ∇u of the expression by fourth-order central differences with step
/// h = 1e-3 × the points' bounding-box diagonal (truncation O(h⁴), far below any
/// discretization error measured here).
FieldErrors field_errors(const FieldQuadrature& quadrature, const VectorExpression& exact,
                         const Eigen::VectorXd& displacement, double time);

/// summary.json's `field_errors`: l2, h1_seminorm, their relative versions (over the
/// exact solution's norms; absent when those are 0), the exact norms and the rule strength.
nlohmann::json field_errors_json(const FieldErrors& errors);

}  // namespace altfem
