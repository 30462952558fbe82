#include "polyhedral/harmonic_tabulation.hpp"

namespace altfem::harmonic {

HarmonicTabulation tabulate_harmonic_element(const ElementHarmonicBasis& basis, const PolyhedronRule& rule,
                                             bool consistent) {
  const int n = basis.node_count();
  const auto points = rule.weights.size();
  HarmonicTabulation tabulation{rule.weights, {}, {}};
  basis.evaluate(rule.points, tabulation.values, tabulation.gradients);
  Eigen::MatrixXd integrated = Eigen::MatrixXd::Zero(n, 3);  // Σ_q w_q ∇N_i(x_q)
  for (Eigen::Index q = 0; q < points; ++q) integrated += rule.weights[q] * tabulation.gradients.middleRows(q * n, n);
  if (consistent) {
    const Eigen::MatrixXd correction = (basis.boundary_integrals() - integrated) / rule.weights.sum();  // #nodes × 3
    for (Eigen::Index q = 0; q < points; ++q) tabulation.gradients.middleRows(q * n, n) += correction;
  }
  return tabulation;
}

}  // namespace altfem::harmonic
