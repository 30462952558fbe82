#pragma once
// Lagrange shape functions of one element type on its reference domain (tets: the
// UNIT tet; hexes: [-1,1]^3), nodes in VTK order (reference_nodes.hpp).
#include <Eigen/Core>
#include <array>
#include <vector>

#include "shared/element/element_type.hpp"

namespace altfem {

/// One Lagrange element type. The basis is built as in Li, "High-order FEM"
/// (thesis, §4.1.2, eqs. 4.17–4.28): with V the Vandermonde matrix of the element's
/// monomials at its nodes (V_ij = m_j(node_i)), N(ξ) = V^{-T} m(ξ), so N_i(node_k) =
/// δ_ik and every polynomial of the space is reproduced exactly. The same code
/// serves all six types (only the node and monomial tables differ); V is at most
/// 27 × 27 and well conditioned on these nodes.
class ReferenceElement {
public:
  /// Upper bound of node_count() over all types (Hex27), for stack buffers.
  static constexpr int max_node_count = 27;

  /// Builds the tables; prefer the shared instances of reference_element(type).
  explicit ReferenceElement(ElementType type);

  ElementType type() const { return type_; }
  ElementShape shape() const { return element_shape(type_); }
  int node_count() const { return static_cast<int>(nodes_.rows()); }
  int degree() const { return element_degree(type_); }
  /// #nodes × 3 reference coordinates, VTK order.
  const Eigen::MatrixXd& nodes() const { return nodes_; }
  /// The reference centroid: (1/4, 1/4, 1/4) for tets, the origin for hexes.
  Eigen::Vector3d centroid() const;

  /// values (#nodes) = N_i(ξ). Writes into the caller's storage; no allocation.
  void evaluate(const Eigen::Vector3d& xi, Eigen::Ref<Eigen::VectorXd> values) const;
  /// gradients (#nodes × 3) = ∂N_i/∂ξ_j. Writes into the caller's storage; no allocation.
  void evaluate_gradients(const Eigen::Vector3d& xi, Eigen::Ref<Eigen::MatrixXd> gradients) const;
  /// hessians (#nodes × 9): column 3j + k = ∂²N_i/∂ξ_j∂ξ_k (each row a row-major 3 × 3
  /// matrix). Writes into the caller's storage; no allocation. For derivative-jump
  /// terms on faces (ghost penalties, Burman 2010) on quadratic cells.
  void evaluate_hessians(const Eigen::Vector3d& xi, Eigen::Ref<Eigen::MatrixXd> hessians) const;

  /// The same at many points at once (points: #points × 3), as matrix products over all
  /// of them: values (#points × #nodes), row q = N(ξ_q)ᵀ. For rules of many points (cut
  /// cells' rules), where one point at a time spends its time in small products.
  void evaluate_at(const Eigen::Ref<const Eigen::MatrixXd>& points, Eigen::MatrixXd& values) const;
  /// gradients[j] (#points × #nodes), row q = ∂N/∂ξ_j(ξ_q)ᵀ.
  void evaluate_gradients_at(const Eigen::Ref<const Eigen::MatrixXd>& points,
                             std::array<Eigen::MatrixXd, 3>& gradients) const;

  /// products (#nodes × #nodes, exactly symmetric) = Σ_q w_q N(ξ_q) N(ξ_q)ᵀ and
  /// integrals (#nodes) = Σ_q w_q N(ξ_q), over points (#points × 3) and weights
  /// (#points): a cell's mass matrix and load integrals, from the basis values at every
  /// point (evaluate_at), one triangle of the products formed. Summed in the nodal basis,
  /// not through the monomials' Gram matrix: with positive weights every diagonal entry
  /// and integral is a sum of non-negative terms, so a sliver's tiny ones stay positive
  /// (in the monomials' basis they cancel to round-off of the larger ones: negative for
  /// a cell cut to 2⁻³⁰ of its volume, as `altfem quadrature conditioning` makes).
  void integrate_products(const Eigen::Ref<const Eigen::MatrixXd>& points,
                          const Eigen::Ref<const Eigen::VectorXd>& weights, Eigen::MatrixXd& products,
                          Eigen::VectorXd& integrals) const;

  /// Whether ξ lies in the reference domain enlarged by `tolerance` (in reference
  /// coordinates): tets ξ_j ≥ −tol and Σξ_j ≤ 1 + tol; hexes |ξ_j| ≤ 1 + tol.
  bool contains(const Eigen::Vector3d& xi, double tolerance) const;

private:
  ElementType type_;
  Eigen::MatrixXd nodes_;                   ///< #nodes × 3
  std::vector<Eigen::Vector3i> exponents_;  ///< #nodes monomial exponents (a, b, c)
  Eigen::MatrixXd coefficients_;            ///< #nodes × #nodes: N(ξ) = coefficients_ · m(ξ)
};

/// The shared, immutable instance of each type (built on first use, thread-safe).
const ReferenceElement& reference_element(ElementType type);

}  // namespace altfem
