#include "polyhedral/harmonic_tabulation.hpp"

namespace altfem::harmonic {

HarmonicTabulation tabulate_harmonic_element(const ElementHarmonicBasis& basis, const PolyhedronRule& rule,
                                             bool consistent) {
  const int n = basis.node_count();
  const auto points = rule.weights.size();
  HarmonicTabulation tabulation{rule.weights, Eigen::MatrixXd(points, n), Eigen::MatrixXd(points * n, 3)};
  Eigen::VectorXd values;
  Eigen::MatrixXd gradients;
  Eigen::MatrixXd integrated = Eigen::MatrixXd::Zero(n, 3);  // Σ_q w_q ∇N_i(x_q)
  for (Eigen::Index q = 0; q < points; ++q) {
    basis.evaluate(rule.points.row(q).transpose(), values, gradients);
    tabulation.values.row(q) = values.transpose();
    tabulation.gradients.middleRows(q * n, n) = gradients;
    integrated += rule.weights[q] * gradients;
  }
  if (consistent) {
    const Eigen::MatrixXd correction = (basis.boundary_integrals() - integrated) / rule.weights.sum();  // #nodes × 3
    for (Eigen::Index q = 0; q < points; ++q) tabulation.gradients.middleRows(q * n, n) += correction;
  }
  return tabulation;
}

}  // namespace altfem::harmonic
