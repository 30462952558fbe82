#pragma once
// Hyperelastic energy, internal forces and tangent stiffness of any list of tabulated
// elements (docs/architecture.md, "The meeting point").
//
// With the displacement u, at each quadrature point F = I + Σ_a u_a ⊗ ∇N_a and
//   Ψ(u)        = Σ_q w_q ψ(F_q)
//   ∂Ψ/∂u_ai    = Σ_q w_q Σ_j P_ij(F_q) ∂_j N_a
//   ∂²Ψ/∂u_ai∂u_bk = Σ_q w_q Σ_jl (∂P_ij/∂F_kl) ∂_j N_a ∂_l N_b.
#include <Eigen/Core>
#include <memory>
#include <span>
#include <vector>

#include "shared/assembly/basis_incidence.hpp"
#include "shared/assembly/block_sparsity.hpp"
#include "shared/assembly/element_masses.hpp"
#include "shared/assembly/tabulated_elements.hpp"
#include "shared/material/material.hpp"

namespace altfem {

class ElasticAssembler {
public:
  /// materials[m] is the material of the elements whose material id is m; the
  /// assembler keeps references to both. `extra_couplings` are block couplings beyond
  /// the elements' own (a method's face terms) that its sparsity pattern must hold.
  ///
  /// `share` (#elements + #extra couplings, nonzero for this rank's) makes it one rank's
  /// share of a run over several processes whose matrices are summed by the solver
  /// (ranks::shares_matrices()): the pattern holds only those blocks (BlockSparsity), and
  /// hessian(), mass_matrix() and add_mass() add only this rank's elements, as
  /// assemble_only() of the share's elements does for energy(), gradient() and hessian().
  ElasticAssembler(const TabulatedElements& elements, std::vector<const Material*> materials,
                   const BasisGroups& extra_couplings = {}, std::span<const char> share = {});
  ~ElasticAssembler();

  /// 3 × the number of basis functions of the elements and the extra couplings.
  int dof_count() const { return static_cast<int>(sparsity_.pattern().rows()); }
  const TabulatedElements& elements() const { return elements_; }
  /// The pattern of hessian() and mass_matrix(), all values zero.
  const SparseMatrix& pattern() const { return sparsity_.pattern(); }
  /// Where each element's and each extra coupling's blocks lie in pattern().
  const BlockSparsity& sparsity() const { return sparsity_; }

  /// Ψ(u); +∞ when a material rejects a deformation (e.g. Neo-Hookean at J ≤ 0).
  double energy(const Eigen::VectorXd& displacement) const;
  /// ∂Ψ/∂u (#dofs). Throws NumericalError naming the element on a non-finite stress.
  void gradient(const Eigen::VectorXd& displacement, Eigen::VectorXd& gradient) const;
  /// ∂²Ψ/∂u² into `hessian`, which must have pattern() (its values are overwritten).
  /// With project_spd, each element matrix is projected to the nearest positive
  /// semi-definite one (eigenvalue clamping; Smith et al. 2018 §4.4, Teran et al. 2005).
  void hessian(const Eigen::VectorXd& displacement, SparseMatrix& hessian, bool project_spd = false) const;
  /// Consistent mass ∫ ρ N_a N_b (times the 3×3 identity), with pattern(); with a `share`,
  /// of this rank's elements.
  void mass_matrix(SparseMatrix& mass) const;
  /// The load of a uniform body acceleration a (#dofs): f_(3b+i) = Σ_q w_q ρ a_i N_b(x_q),
  /// i.e. ∫ ρ a·φ_b dV for any basis, not only a partition of unity.
  Eigen::VectorXd body_force(const Eigen::Vector3d& acceleration) const;
  /// Lumped mass (#dofs) by HRZ: the diagonal of the consistent mass scaled so
  /// each element keeps its mass (Hinton, Rock & Zienkiewicz 1976). Plain row sums give
  /// zero or negative corner masses for quadratic tets; HRZ stays positive.
  Eigen::VectorXd lumped_mass() const;
  /// The same three from other rules of the same elements, reduced per element (one
  /// entry per element, in order; ElementMasses): the FCM's mass rules.
  void mass_matrix(const ElementMasses& masses, SparseMatrix& mass) const;
  /// matrix += factor · M, element by element, into a matrix with pattern(): what
  /// mass_matrix() would add, without a matrix of the mass of its own.
  void add_mass(const ElementMasses& masses, double factor, SparseMatrix& matrix) const;
  /// M v (#dofs), element by element.
  Eigen::VectorXd mass_times(const ElementMasses& masses, const Eigen::VectorXd& vector) const;
  Eigen::VectorXd body_force(const ElementMasses& masses, const Eigen::Vector3d& acceleration) const;
  Eigen::VectorXd lumped_mass(const ElementMasses& masses) const;
  /// Per element the Cauchy stress σ = P Fᵀ / det F averaged over its quadrature points
  /// (weights w_q |det J|): #elements × 9, row e holding σ row-major (zero for an element
  /// another rank holds: TabulatedElements::keep_only). For output.
  Eigen::MatrixXd mean_cauchy_stress(const Eigen::VectorXd& displacement) const;
  /// Whether every material's tangent is independent of F (linear elasticity): then
  /// the Hessian needs assembling and factorising only once.
  bool is_linear() const;
  /// A constant shift of F at every quadrature point (9 values per point, column-major, in
  /// the whole tabulation's point order: TabulatedElements::whole_point_offset; not owned,
  /// read at every assembly), or an empty span for none: F = I + Σ_a u_a ⊗ ∇N_a + shift.
  /// DG's lifted Dirichlet data (dg/lifted_gradients.hpp).
  void set_deformation_shifts(std::span<const double> shifts);
  /// Makes energy(), gradient() and hessian() sum only the elements whose `owned` entry is
  /// nonzero (#elements), the others counting zero: one rank's share of a run over several
  /// processes (tabulated_discretization.cpp sums the shares). The mass, the loads and
  /// the stresses stay whole.
  void assemble_only(const std::vector<char>& owned);
  /// Whether energy(), gradient() and hessian() include element e (assemble_only).
  bool assembles(int element) const { return owned_.empty() || owned_[element]; }

private:
  struct Scratch;
  /// Element e's first point's deformation shift, or nullptr when there are none.
  const double* element_shifts(int element) const;
  void check_materials() const;
  void check_masses(const ElementMasses& masses) const;
  /// OpenMP's current thread count, at most the number of scratch blocks.
  int active_threads() const;
  /// body(element index) for every element, colour by colour, in parallel within a colour.
  template <typename Body>
  void for_each_colored_element(Body&& body) const;

  const TabulatedElements& elements_;
  std::vector<const Material*> materials_;
  BlockSparsity sparsity_;
  std::vector<std::vector<int>> colors_;
  std::vector<char> owned_;                     // empty: every element is assembled
  std::vector<std::vector<int>> owned_colors_;  // with owned_: colors_ restricted to the owned elements
  bool share_pattern_ = false;                  // constructed with a share: the matrices hold owned_ only
  BasisIncidence incidence_;
  const double* shifts_ = nullptr;  // set_deformation_shifts', or null
  // Per-element results kept between calls, so that assembly does not allocate: the
  // gradient's forces (3 per incidence slot) and the energy's element energies.
  // Like the scratch, they make concurrent calls on one assembler unsafe.
  mutable std::vector<double> element_forces_;
  mutable std::vector<double> element_energies_;
  // One per thread. Fixed-size elements never touch it; elements of other sizes
  // resize it, which allocates only when consecutive elements differ in size.
  std::unique_ptr<Scratch[]> scratch_;
  int threads_ = 1;
};

}  // namespace altfem
