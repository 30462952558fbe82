#pragma once
// The element masses (ElementMasses) of a Lagrange mesh straight from its cells'
// rules, without tabulating gradients: what a method needs of rules that serve only
// the mass matrix and the loads, once (the FCM's cut-cell mass rules, Longva et al.
// 2020 §6, run to millions of points).
#include <Eigen/Core>
#include <unordered_map>

#include "shared/assembly/element_masses.hpp"
#include "shared/element/element_type.hpp"
#include "shared/fem/tabulate_lagrange.hpp"
#include "shared/mesh/volume_mesh.hpp"
#include "shared/quadrature/quadrature_rule.hpp"

namespace altfem {

/// A rule reduced on the reference element (ReferenceElement::integrate_products):
/// products (#nodes × #nodes) = Σ_q w_q N(ξ_q) N(ξ_q)ᵀ, integrals (#nodes) = Σ_q w_q N(ξ_q),
/// weight_sum = Σ_q w_q. An affine cell's masses are det J times these, so a mass rule of
/// thousands of points is read once and a rebuild after an event takes its reduction.
struct ReferenceProducts {
  Eigen::MatrixXd products;
  Eigen::VectorXd integrals;
  double weight_sum = 0;
};

/// A rule of more points than this is summed by all threads (in reference_products and
/// lagrange_element_masses; called inside a parallel region, by that region's thread): the
/// tip of a sharpened pencil is one cell with thousands of clipped pieces, a strength-8 rule
/// on each, and was most of a cut's integration on one thread while the other cells took
/// the rest.
constexpr Eigen::Index large_rule_points = 50000;

ReferenceProducts reference_products(ElementType type, const QuadratureRule& rule);

/// One entry per cell of `mesh`, in order: Σ_q w_q |det J(ξ_q)| N_a(ξ_q) N_b(ξ_q) and
/// Σ_q w_q |det J| N_a(ξ_q) over the cell's rule (`rules.custom`, else `rules.standard`);
/// an affine cell in `reduced` (cell → its rule's reduction) takes det J times that instead
/// of reading its rule. OpenMP-parallel over cells. Throws NumericalError naming the cell
/// where det J ≤ 0.
ElementMasses lagrange_element_masses(const VolumeMesh& mesh, const LagrangeCellRules& rules,
                                      const std::unordered_map<int, ReferenceProducts>& reduced = {});

}  // namespace altfem
