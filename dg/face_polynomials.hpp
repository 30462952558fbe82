#pragma once
// Polynomials on a DG face, written in one element's frame ξ = (x − c)/h: the traces of
// both neighbours' monomials (and of their derivatives), and products of them
// integrated exactly from the face's moments (Kaufmann et al. 2009 §5).
#include <Eigen/Core>
#include <array>
#include <vector>

#include "dg/monomial_basis.hpp"

namespace altfem::dg {

/// Coefficients over the frame's monomials up to a degree, in monomial_index order.
using Polynomial = Eigen::VectorXd;

struct FunctionsInFrame {
  std::vector<Polynomial> values;                    ///< #functions
  std::vector<std::array<Polynomial, 3>> gradients;  ///< #functions × 3: ∂/∂x_d (physical)
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
  /// ∫_f p q dA.
  double product(const Polynomial& p, const Polynomial& q) const;

private:
  Eigen::VectorXd moments_;
  Eigen::Matrix<int, Eigen::Dynamic, 3> exponents_;
};

}  // namespace altfem::dg
