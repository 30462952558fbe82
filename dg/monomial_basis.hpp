#pragma once
// The basis of one DG element (Kaufmann et al. 2009 §5): the monomials ((x − c)/h)^α of
// total degree |α| ≤ k, centred at the element's centroid c and scaled by its size h so
// that they are O(1) on the element whatever its size and position (the matrices stay
// well conditioned). k = 1, 2, 3 gives 4, 10, 20 functions, in monomial_index order.
#include <Eigen/Core>

#include "shared/geometry/monomial_index.hpp"
#include "shared/geometry/polyhedron.hpp"

namespace altfem::dg {

class MonomialBasis {
public:
  MonomialBasis(int degree, const Eigen::Vector3d& centre, double scale);

  int degree() const { return degree_; }
  int size() const { return static_cast<int>(exponents_.rows()); }
  const Eigen::Vector3d& centre() const { return centre_; }
  double scale() const { return scale_; }
  /// The exponents α of each function: #functions × 3.
  const Eigen::Matrix<int, Eigen::Dynamic, 3>& exponents() const { return exponents_; }
  /// φ_a(x) (#functions) and ∇φ_a(x) (#functions × 3).
  void evaluate(const Eigen::Vector3d& x, Eigen::VectorXd& values, Eigen::MatrixXd& gradients) const;

  /// Replaces the functions by combinations of the monomials m: φ_j = Σ_a C_aj m_a
  /// (C: #functions square, invertible), e.g. the constrained and free directions of a
  /// strongly imposed condition (dg/strong_conditions.hpp). evaluate() and the exact
  /// integrals then refer to the φ_j; exponents() still lists the monomials m_a.
  void combine(Eigen::MatrixXd combination);
  /// C, or empty while the functions are the monomials themselves.
  const Eigen::MatrixXd& combination() const { return combination_; }

private:
  int degree_;
  Eigen::Vector3d centre_;
  double scale_;
  Eigen::Matrix<int, Eigen::Dynamic, 3> exponents_;
  Eigen::MatrixXd combination_;
};

/// The basis of `cell`: centred at its centroid, scaled by its diameter (Kaufmann et al. §5).
MonomialBasis cell_monomial_basis(const Polyhedron& cell, int degree);

}  // namespace altfem::dg
