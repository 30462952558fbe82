#include "dg/exact_element_matrices.hpp"

#include "shared/geometry/polyhedron_moments.hpp"

namespace altfem::dg {

ElementMatrices exact_element_matrices(const Polyhedron& element, const MonomialBasis& basis, double lambda, double mu,
                                       double density) {
  const int n = basis.size();
  const auto& alpha = basis.exponents();
  // ∫ ξ^γ dV for |γ| ≤ 2k, ξ = (x − c)/h: every product below is one of these.
  const Eigen::VectorXd moments = polyhedron_moments(element, 2 * basis.degree(), basis.centre(), basis.scale());
  const auto moment = [&](const Eigen::Matrix<int, 1, 3>& exponent) { return moments[monomial_index(exponent)]; };
  const double inverse_scale_squared = 1.0 / (basis.scale() * basis.scale());

  ElementMatrices matrices{Eigen::MatrixXd::Zero(3 * n, 3 * n), Eigen::MatrixXd(n, n), Eigen::VectorXd(n)};
  for (int a = 0; a < n; ++a) {
    matrices.integrals[a] = moment(alpha.row(a));
    for (int b = 0; b < n; ++b) {
      matrices.mass(a, b) = density * moment(alpha.row(a) + alpha.row(b));
      // G(j, l) = ∫ ∂_j φ_a ∂_l φ_b dV, with ∂_j ξ^α = α_j / h ξ^(α − e_j).
      Eigen::Matrix3d G = Eigen::Matrix3d::Zero();
      for (int j = 0; j < 3; ++j)
        for (int l = 0; l < 3; ++l) {
          if (alpha(a, j) == 0 || alpha(b, l) == 0) continue;
          Eigen::Matrix<int, 1, 3> exponent = alpha.row(a) + alpha.row(b);
          --exponent(j);
          --exponent(l);
          G(j, l) = alpha(a, j) * alpha(b, l) * inverse_scale_squared * moment(exponent);
        }
      // K_(ai)(bk) = μ δ_ik tr G + μ G(k, i) + λ G(i, k)   (test φ_a e_i, trial φ_b e_k)
      for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k)
          matrices.stiffness(3 * a + i, 3 * b + k) = (i == k ? mu * G.trace() : 0.0) + mu * G(k, i) + lambda * G(i, k);
    }
  }
  const Eigen::MatrixXd& combination = basis.combination();
  if (combination.size() == 0) return matrices;
  // Functions φ_j = Σ_a C_aj m_a: each matrix transforms as Cᵀ A C, the stiffness per component.
  Eigen::MatrixXd vector_combination = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  for (int a = 0; a < n; ++a)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < 3; ++i) vector_combination(3 * a + i, 3 * j + i) = combination(a, j);
  matrices.stiffness = vector_combination.transpose() * matrices.stiffness * vector_combination;
  matrices.mass = combination.transpose() * matrices.mass * combination;
  matrices.integrals = combination.transpose() * matrices.integrals;
  return matrices;
}

}  // namespace altfem::dg
