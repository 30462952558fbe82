// Example 3: the finite cell method's quadrature for ONE cut cell, step by step
// (Longva et al. 2020, §4.4–4.5, Fig. 3).
//
//   build/bin/ex3_cut_cell
//
// An FCM background cell that the object's surface cuts must integrate only over the
// part of the cell inside the object. altfem does this in two steps:
//   1. intersection (§4.5): clip every tetrahedron of the object's own tetrahedral mesh
//      by the cell, split the convex pieces into tetrahedra Q and put a degree-m rule on
//      each; its points, mapped back to the cell's reference domain with the weights of
//      eqs. (11)–(12), integrate any polynomial of degree ≤ m over cell ∩ object exactly
//      — but they are many (hundreds per cell);
//   2. simplification (§4.4, eq. (10)): keep at most M = C(m+3, 3) of those points with
//      new positive weights that integrate the same polynomials to the same values.
// compute_cell_rules does exactly this for every cell of a mesh, in parallel.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "shared/cut_cells/cut_cell_rule.hpp"
#include "shared/element/reference_element.hpp"
#include "shared/geometry/analytic_shape.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "shared/mesh/tetrahedralize.hpp"
#include "shared/quadrature/simplify_quadrature.hpp"

using namespace altfem;

// Σ_q w_q |J| x_q^α, the rule's integral of the monomial x^α over the physical cut cell
// (the cell is a box, so the map ξ ↦ x is affine and |J| constant).
double integrate_monomial(const QuadratureRule& rule, const CellGeometry& cell, const Eigen::Vector3i& exponent) {
  const ReferenceElement& hex8 = reference_element(ElementType::hex8);
  Eigen::VectorXd shape(8);
  double sum = 0;
  for (Eigen::Index q = 0; q < rule.points.rows(); ++q) {
    const Eigen::Vector3d xi = rule.points.row(q).transpose();
    hex8.evaluate(xi, shape);
    const Eigen::Vector3d x = cell.corners().transpose() * shape;
    sum += rule.weights[q] * cell.jacobian_determinant(xi) * std::pow(x.x(), exponent.x()) *
           std::pow(x.y(), exponent.y()) * std::pow(x.z(), exponent.z());
  }
  return sum;
}

int main() {
  // The background cell: one Hex20 of the unit cube (its corners give the geometry).
  const VolumeMesh background =
      structured_grid({Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()}, {1, 1, 1}, ElementType::hex20);
  Eigen::MatrixXd corners(8, 3);
  for (int a = 0; a < 8; ++a) corners.row(a) = background.nodes.row(background.cells(0, a));
  const CellGeometry cell(ElementType::hex20, corners);

  // The object: a ball of radius 1 centred off the cell's corner, so its surface cuts
  // the cell along a curved cap; it reaches FCM as a Tet4 mesh (CGAL Mesh_3).
  const Eigen::Vector3d centre(-0.1, 0.2, 0.05);
  const double radius = 1.0;
  const ShapePointer ball = make_sphere(centre, radius);
  const VolumeMesh embedded = tetrahedralize_shape(*ball, 0.2);
  std::vector<TetrahedronCorners> tetrahedra(embedded.cells.rows());
  for (Eigen::Index t = 0; t < embedded.cells.rows(); ++t)
    for (int a = 0; a < 4; ++a) tetrahedra[t].row(a) = embedded.nodes.row(embedded.cells(t, a));
  std::printf("cell: Hex20 [0,1]^3; object: ball r = %.1f, %lld tetrahedra\n", radius,
              static_cast<long long>(tetrahedra.size()));

  // 1. Intersection rule of degree m = 4 (CellRuleOptions' default order): a
  //    degree-4 rule on every piece Q of cell ∩ tetrahedron. Tetrahedra that miss the
  //    cell contribute nothing.
  const int order = 4;
  const IntersectionRule intersection = intersection_rule(cell, tetrahedra, order);
  const QuadratureRule& exact_rule = intersection.rule;
  const double rule_volume = integrate_monomial(exact_rule, cell, {0, 0, 0});
  std::printf("intersection rule: %lld points, volume %.12f (clipped pieces: %.12f)\n",
              static_cast<long long>(exact_rule.points.rows()), rule_volume, intersection.clipped_volume);

  // 2. Simplification to at most M = C(m+3, 3) points (§4.4), Carathéodory–Steinitz
  //    recombination (the default simplifier) on the Chebyshev moment system.
  const int limit = (order + 1) * (order + 2) * (order + 3) / 6;
  const SimplificationResult simplified = simplify_quadrature(exact_rule, {.degree = order});
  const QuadratureRule& rule = simplified.rule;
  std::printf("simplified rule: %lld points (M = %d), moment residual %.2e, min weight %.3e\n",
              static_cast<long long>(rule.points.rows()), limit, simplified.residual, rule.weights.minCoeff());

  // 3. Every kept point is one of the intersection rule's points, so it lies in the cell
  //    (reference [-1,1]³) and in the object (the ball, up to Mesh_3's surface distance).
  double farthest_outside_cell = 0, farthest_outside_ball = -INFINITY;
  const ReferenceElement& hex8 = reference_element(ElementType::hex8);
  Eigen::VectorXd shape(8);
  for (Eigen::Index q = 0; q < rule.points.rows(); ++q) {
    const Eigen::Vector3d xi = rule.points.row(q).transpose();
    farthest_outside_cell = std::max(farthest_outside_cell, xi.cwiseAbs().maxCoeff() - 1.0);
    hex8.evaluate(xi, shape);
    farthest_outside_ball = std::max(farthest_outside_ball, ball->level_set(cell.corners().transpose() * shape));
  }
  std::printf("points: max(|xi|_inf - 1) = %.2e, max level set of the ball = %.2e\n", farthest_outside_cell,
              farthest_outside_ball);

  // 4. The simplified rule against the intersection rule on monomials x^a y^b z^c: equal
  //    (to round-off) up to degree m, not beyond — the price of M points.
  std::printf("\n%10s %8s %20s %20s %10s\n", "x^a y^b z^c", "degree", "intersection", "simplified", "rel. diff.");
  double worst_exact_degree = 0, beyond = 0;
  for (const Eigen::Vector3i& exponent :
       {Eigen::Vector3i(0, 0, 0), Eigen::Vector3i(1, 0, 0), Eigen::Vector3i(0, 2, 1), Eigen::Vector3i(2, 1, 1),
        Eigen::Vector3i(0, 0, 4), Eigen::Vector3i(3, 2, 1), Eigen::Vector3i(0, 6, 2)}) {
    const double reference = integrate_monomial(exact_rule, cell, exponent);
    const double value = integrate_monomial(rule, cell, exponent);
    const double difference = std::abs(value - reference) / std::abs(reference);
    const int degree = exponent.sum();
    double& worst = degree <= order ? worst_exact_degree : beyond;
    worst = std::max(worst, difference);
    std::printf("  (%d,%d,%d) %8d %20.14f %20.14f %10.2e\n", exponent.x(), exponent.y(), exponent.z(), degree,
                reference, value, difference);
  }

  const bool ok = simplified.simplified && !simplified.failed && rule.points.rows() <= limit &&
                  rule.points.rows() < exact_rule.points.rows() && simplified.residual <= 1e-12 &&
                  rule.weights.minCoeff() > 0 && farthest_outside_cell <= 1e-12 && farthest_outside_ball <= 1e-3 &&
                  std::abs(rule_volume - intersection.clipped_volume) <= 1e-12 * rule_volume &&
                  worst_exact_degree <= 1e-10 && beyond > 1e-8;
  std::printf("\n%s: at most M positive points inside the cut cell, exact to degree %d\n",
              ok ? "verified" : "NOT verified", order);
  return ok ? 0 : 1;
}
