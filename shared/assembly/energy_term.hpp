#pragma once
// An energy a method adds to its volume elements: DG's face fluxes, a ghost penalty,
// weakly imposed boundary conditions (docs/architecture.md, "Adding a method"). The
// term declares the block couplings it needs, so that the Hessian, the mass matrix and
// every matrix the integrators build share one sparsity pattern.
#include <Eigen/Core>
#include <vector>

#include "shared/assembly/basis_groups.hpp"
#include "shared/assembly/block_sparsity.hpp"

namespace altfem {

class EnergyTerm {
public:
  virtual ~EnergyTerm() = default;
  /// The lists of basis functions the term couples (each list all-to-all).
  virtual const BasisGroups& couplings() const = 0;
  /// Called once, before any assembly, with the pattern built from the elements and
  /// every term's couplings: list g of couplings() is the pattern's extra group
  /// first_group + g.
  virtual void bind(const BlockSparsity& sparsity, int first_group) = 0;
  virtual double energy(const Eigen::VectorXd& displacement) const = 0;
  /// Adds ∂E/∂u to `gradient` (#dofs).
  virtual void add_gradient(const Eigen::VectorXd& displacement, Eigen::VectorXd& gradient) const = 0;
  /// Adds ∂²E/∂u² to `hessian`'s values (the bound pattern).
  virtual void add_hessian(const Eigen::VectorXd& displacement, SparseMatrix& hessian) const = 0;
  /// True when the term is quadratic in u (its Hessian is constant).
  virtual bool is_quadratic() const = 0;
  /// Makes energy(), add_gradient() and add_hessian() include only the couplings() lists
  /// whose `owned` entry is nonzero: one rank's share in a run over several processes.
  /// False when the term cannot divide itself; then rank 0 assembles it whole.
  virtual bool assemble_only(const std::vector<char>& /*owned*/) { return false; }
};

}  // namespace altfem
