#pragma once
// Polynomials on a DG face, written in one element's frame ξ = (x − c)/h: the traces of
// both neighbours' monomials (and of their derivatives), and products of them
// integrated exactly from the face's moments (Kaufmann et al. 2009 §5).
#include <Eigen/Core>
#include <array>

#include "dg/monomial_basis.hpp"

namespace altfem::dg {

/// Polynomials are coefficient columns over the frame's monomials up to a degree, in
/// monomial_index order.
struct FunctionsInFrame {
  Eigen::MatrixXd values;                    ///< #frame monomials × #functions: each function's coefficients
  std::array<Eigen::MatrixXd, 3> gradients;  ///< each #frame monomials × #functions: ∂/∂x_d (physical)
};

/// Each function of `basis` and its gradient as polynomials of degree ≤ `degree` in the
/// frame (centre, scale).
FunctionsInFrame in_frame(const MonomialBasis& basis, const Eigen::Vector3d& centre, double scale, int degree);

/// Exact integrals of products of polynomials of degree ≤ `degree` over a planar
/// polygon, from its moments ∫ ξ^γ dA, |γ| ≤ 2·degree, in the frame (centre, scale).
class FaceIntegrals {
public:
  /// polygon: #vertices × 3, planar.
  FaceIntegrals(const Eigen::MatrixXd& polygon, int degree, const Eigen::Vector3d& centre, double scale);
  /// ∫_f p_a q_b dA for every column p_a of p and q_b of q (polynomial coefficients,
  /// #frame monomials × #a and × #b): #a × #b, as pᵀ M q with M_ij = ∫ ξ^(α_i + α_j) dA.
  Eigen::MatrixXd products(const Eigen::MatrixXd& p, const Eigen::MatrixXd& q) const {
    return p.transpose() * (monomial_products_ * q);
  }

private:
  Eigen::MatrixXd monomial_products_;  // #frame monomials square: M
};

}  // namespace altfem::dg
