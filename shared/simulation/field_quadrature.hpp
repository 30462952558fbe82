#pragma once
// A method's basis at quadrature points covering its domain, with the points' positions:
// what integrating a scene's expressions against the basis (body-force loads) and
// measuring a solution against an exact one (field errors) need from any method.
#include <Eigen/Core>
#include <memory>

#include "shared/assembly/tabulated_elements.hpp"
#include "shared/scene/vector_expression.hpp"

namespace altfem {

struct FieldQuadrature {
  /// Weights w_q |det J|, basis values and physical gradients per element. Shared, so a
  /// method may hand out the tabulation its discretization already holds.
  std::shared_ptr<const TabulatedElements> elements;
  /// #points × 3 rest positions, in the elements' packed point order (element 0's
  /// points first).
  Eigen::MatrixXd points;
  /// The polynomial degree the rule integrates exactly (on cut cells: the moments the
  /// simplified rule matches).
  int strength = 0;
};

/// For a nodal basis that reproduces linear fields (Lagrange elements, the FCM's
/// background cells, harmonic bases): x_q = Σ_a N_a(x_q) X_a, with X_a = nodes.row(a)
/// (#nodes × 3). Exact for isoparametric Lagrange cells; to the fit for MFS harmonic cells.
Eigen::MatrixXd nodal_quadrature_points(const TabulatedElements& elements, const Eigen::MatrixXd& nodes);

/// A view of tabulated elements the caller keeps alive (no ownership).
inline std::shared_ptr<const TabulatedElements> borrowed(const TabulatedElements& elements) {
  return {std::shared_ptr<const TabulatedElements>(), &elements};
}

/// An expression's values (#points × 3) at points (#points × 3) and time t, chunks of
/// points in parallel (OpenMP, each chunk with its own parser). Throws NumericalError when
/// a value is not finite.
Eigen::MatrixXd evaluate_at_points(const VectorExpression& expression, const Eigen::MatrixXd& points, double time);

}  // namespace altfem
