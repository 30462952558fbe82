#pragma once
// Corotated linear elasticity by stiffness warping, for any nodal method (Müller & Gross
// 2004, "Interactive Virtual Materials"; Martin et al. 2008 §6 for polyhedral elements):
// each element keeps its linear stiffness K_e (3n × 3n, from the rest state) and sees the
// deformation through its rotation R_e, taken from its nodes by shape matching: the polar
// rotation of the mass-weighted affine fit of the deformed nodes to the rest ones
// (best_fit_rotation.hpp). With the element's rest node positions X and deformed
// ones x = X + u (each 3n, node-major), the warped internal force is
//   f_e = R_e K_e (R_eᵀ x − X)          (R_e acting on every node's 3-block),
// which vanishes for every rigid motion x = Q X + t (R_e = Q, K_e kills translations).
//
// Warping is a force model, not the gradient of an energy (R_e depends on u). The
// Discretization interface is met with
//   energy(u)   = Σ_e ½ z_eᵀ K_e z_e,  z_e = R_eᵀ x − X   (R_e from u),
//   gradient(u) = Σ_e f_e                                  (the energy's gradient with R_e frozen),
//   hessian(u)  = Σ_e R_e K_e R_eᵀ                          (R_e frozen; symmetric positive semi-definite).
// The dropped ∂R/∂u terms are of order |strain| · |K| (the derivative of R contracted with
// the element's stress), small for the small strains a linear material is meant for: Newton
// with the frozen-rotation tangent then converges linearly with a small contraction factor,
// and the energy serves its line search as a merit function (Newton also accepts a full
// step that halves the residual). At u = 0 the Hessian is the linear stiffness K, and the
// semi-implicit step (one Newton iteration) is Müller & Gross's warped step exactly.
//
// Everything else (mass, loads, Dirichlet data) is the linear discretization's: the
// forwarding base hands it on.
#include <memory>
#include <vector>

#include "shared/assembly/tabulated_discretization.hpp"
#include "shared/solve/forwarding_discretization.hpp"

namespace altfem {

namespace warped_linear {
// The linear discretization the warping rotates, built (and its parts checked) before
// the forwarding base that refers to it.
struct LinearPart {
  explicit LinearPart(DiscretizationParts parts);
  std::vector<const Material*> materials;
  std::unique_ptr<TabulatedDiscretization> linear;
};
}  // namespace warped_linear

class WarpedLinearDiscretization final : private warped_linear::LinearPart, public ForwardingDiscretization {
public:
  /// parts: elements of a nodal basis (basis function a is the node at rest_positions.row(a)),
  /// every material linear (Material::is_linear), no extra energy terms; rest_positions:
  /// #basis × 3. Throws std::invalid_argument otherwise.
  WarpedLinearDiscretization(DiscretizationParts parts, Eigen::MatrixX3d rest_positions);
  ~WarpedLinearDiscretization() override;

  double energy(const Eigen::VectorXd& u) const override;
  void gradient(const Eigen::VectorXd& u, Eigen::VectorXd& gradient) const override;
  /// Σ_e R_e K_e R_eᵀ; already positive semi-definite, so project_spd changes nothing.
  void hessian(const Eigen::VectorXd& u, Eigen::SparseMatrix<double>& hessian, bool project_spd) const override;
  bool hessian_is_constant() const override { return false; }
  /// A force model: the "energy" is a line-search merit only (see the class comment).
  bool forces_have_potential() const override { return false; }
  /// Per element R_e σ̄(z_e) R_eᵀ: the linear stress of the corotated displacement averaged
  /// over the element's points, turned back into the deformed frame (#elements × 9, row-major).
  Eigen::MatrixXd element_cauchy_stress(const Eigen::VectorXd& u) const override;

  /// R_e of every element for the displacement u (#elements; over several ranks, of the
  /// elements this rank holds, the others' left as they were).
  std::vector<Eigen::Matrix3d> rotations(const Eigen::VectorXd& u) const;
  const TabulatedElements& elements() const { return linear->elements(); }

private:
  // R_e into rotations_, z_e into corotated_ and K_e z_e into stiffness_forces_: for
  // every element, or with own_elements_only for those this rank assembles.
  void warp(const Eigen::VectorXd& u, bool own_elements_only) const;

  Eigen::MatrixX3d rest_;
  std::vector<Eigen::MatrixXd> stiffness_;    // per element K_e, 3n × 3n, local DOF 3a+i
  std::vector<Eigen::VectorXd> node_masses_;  // per element the shape-matching masses (n)
  std::vector<std::vector<int>> colors_;
  struct NodeScratch {
    Eigen::MatrixXd rest, deformed;  // the element's node positions, n × 3
  };
  mutable std::vector<NodeScratch> scratch_;  // one per thread
  // Per-element results of warp(), packed like the elements' basis lists (3 per entry);
  // reused between calls, so assembly does not allocate (and calls must not overlap).
  mutable std::vector<Eigen::Matrix3d> rotations_;
  mutable std::vector<double> corotated_;
  mutable std::vector<double> stiffness_forces_;
};

}  // namespace altfem
