#pragma once
// The Discretization of linear-elastic DG (Kaufmann et al. 2009 §4): the energy
// ½ uᵀ K u with the exactly integrated stiffness K of volume and face terms (weak
// Dirichlet conditions included), the exact consistent mass — block-diagonal by element,
// so explicit steps invert it block by block (§4.3) — exact body-force loads, and the
// boundary data of the weak conditions as a time-dependent load. Strongly imposed
// conditions (dg/strong_conditions.hpp) constrain DOFs, as fem's nodal ones do.
#include <functional>
#include <optional>
#include <vector>

#include "shared/solve/dirichlet_dofs.hpp"
#include "shared/solve/discretization.hpp"

namespace altfem::dg {

/// Block Jacobi for PCG: one dense block per element (AdditiveSchwarzPreconditioner
/// with disjoint blocks). element_dofs: each element's DOFs.
PreconditionerFactory block_jacobi_factory(std::vector<std::vector<int>> element_dofs);

/// The two-level preconditioner for PCG (shared/solve/two_level_preconditioner.hpp; Dobrev,
/// Lazarov, Vassilevski & Zikatanov 2006): the symmetric V-cycle of the damped block Jacobi
/// smoother on element_dofs and the coarse space `prolongation` (#dofs × #coarse, e.g.
/// vertex_coarse_space's), whose iterations stay bounded under refinement.
PreconditionerFactory two_level_factory(std::vector<std::vector<int>> element_dofs,
                                        Eigen::SparseMatrix<double> prolongation);

/// The multilevel preconditioner for PCG: the two-level cycle of two_level_factory whose
/// coarse solve is itself a V-cycle over `grid_prolongations` (dg/grid_coarse_levels.hpp; each
/// level smoothed by a forward and a backward multicolour Gauss–Seidel sweep over its
/// vertices' 3 × 3 blocks), exact (CHOLMOD) only on the coarsest grid. The vertex level alone
/// costs as much to factorise as a tenth of the DG system (a 5 × 5 × 3 vertex stencil: its
/// factor fills 2M entries on the 10³ grid), which is what the cycle avoids.
PreconditionerFactory multilevel_factory(std::vector<std::vector<int>> element_dofs,
                                         Eigen::SparseMatrix<double> vertex_prolongation,
                                         std::vector<Eigen::SparseMatrix<double>> grid_prolongations);

class LinearDgDiscretization : public Discretization {
public:
  /// stiffness, mass: #dofs square, symmetric (taken: pass them moved where the caller
  /// needs no copy); function_integrals: ∫ ρ φ_a dV per basis function (#dofs / 3);
  /// element_dofs: each element's DOFs (disjoint, covering all); weak_condition_load: the
  /// Dirichlet data's load at a time (#dofs); strong: the DOFs that strongly imposed
  /// conditions fix, and their values over time (none by default); share_row_owners: over
  /// several ranks, when `stiffness` is this rank's share (DgLinearSystem::share_row_owners,
  /// #dofs / 3; the mass stays whole), each function's rank; empty when K is the whole.
  LinearDgDiscretization(Eigen::SparseMatrix<double> stiffness, Eigen::SparseMatrix<double> mass,
                         Eigen::VectorXd function_integrals, std::vector<std::vector<int>> element_dofs,
                         std::function<Eigen::VectorXd(double)> weak_condition_load, DirichletDofs strong = {},
                         std::vector<int> share_row_owners = {});

  int dof_count() const override { return static_cast<int>(stiffness_.rows()); }
  /// ½ uᵀ K u and K u, summed over the ranks' shares of K.
  double energy(const Eigen::VectorXd& u) const override;
  void gradient(const Eigen::VectorXd& u, Eigen::VectorXd& gradient) const override;
  void hessian(const Eigen::VectorXd&, Eigen::SparseMatrix<double>& hessian, bool) const override {
    hessian = stiffness_;
  }
  const Eigen::SparseMatrix<double>& hessian_pattern() const override { return stiffness_; }
  const std::vector<int>& matrix_share_owners() const override { return share_row_owners_; }
  bool hessian_is_constant() const override { return true; }
  /// On the stiffness's pattern (with shares, this rank's cells' blocks), built on the first call. The integrators do
  /// not ask for it (mass_times, add_mass): it would hold as many entries as K, most of them zeros. Not thread-safe on
  /// that first call.
  const Eigen::SparseMatrix<double>& mass_matrix() const override;
  /// M v by the element blocks.
  Eigen::VectorXd mass_times(const Eigen::VectorXd& vector) const override { return block_mass_ * vector; }
  /// matrix += factor M, each element block's entries added where K's pattern holds them
  /// (their positions found on the first call; not thread-safe on that call); with
  /// shares, only the blocks of this rank's functions.
  void add_mass(double factor, Eigen::SparseMatrix<double>& matrix) const override;
  /// Built on the first call (only symplectic Euler and its time-step estimate ask).
  const ExplicitMass& explicit_mass() const override;
  /// f_(3a+i) = a_i ∫ ρ φ_a dV.
  Eigen::VectorXd body_force(const Eigen::Vector3d& acceleration) const override;
  Eigen::VectorXd external_force(double time) const override { return weak_condition_load_(time); }
  const std::vector<int>& constrained_dofs() const override { return strong_.dofs; }
  const std::vector<ConstraintHolders>& constraint_holders() const override { return strong_.holders; }
  Eigen::VectorXd prescribed_displacement(double time) const override {
    return strong_.dofs.empty() ? Eigen::VectorXd() : strong_.prescribed(time);
  }
  bool imposes_conditions_weakly() const override { return strong_.dofs.empty(); }
  PreconditionerFactory preconditioner_factory() const override { return preconditioner_; }
  /// Replaces the block Jacobi of iterative solvers (e.g. by two_level_factory).
  void use_preconditioner(PreconditionerFactory factory) { preconditioner_ = std::move(factory); }
  const CoarseSpace& coarse_space() const override { return coarse_space_; }
  /// The coarse level PETSc's multigrid may work on (affine_coarse_space.hpp).
  void use_coarse_space(CoarseSpace space) { coarse_space_ = std::move(space); }

private:
  Eigen::SparseMatrix<double> stiffness_;                    // its pattern holds block_mass_'s
  Eigen::SparseMatrix<double> block_mass_;                   // block diagonal, each cell's block
  mutable std::optional<Eigen::SparseMatrix<double>> mass_;  // block_mass_ on the stiffness's pattern
  mutable std::vector<Eigen::Index> mass_positions_;         // per block_mass_ entry, its index in K's values
  Eigen::VectorXd function_integrals_;
  std::vector<std::vector<int>> element_dofs_;
  mutable std::optional<BlockDiagonalMass> explicit_mass_;
  std::function<Eigen::VectorXd(double)> weak_condition_load_;
  DirichletDofs strong_;
  PreconditionerFactory preconditioner_;
  CoarseSpace coarse_space_;
  std::vector<int> share_row_owners_;  // per function, over several ranks with shares; else empty
};

}  // namespace altfem::dg
