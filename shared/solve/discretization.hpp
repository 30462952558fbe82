#pragma once
// What a method gives the time integrators (docs/architecture.md, "Core
// abstractions"). Nothing here assumes a nodal basis: body forces come as load vectors
// integrated against the basis, explicit steps use the method's own mass inverse, and
// a method may impose its boundary conditions weakly inside its energy (Nitsche,
// penalty) and constrain no DOF at all.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <algorithm>
#include <stdexcept>
#include <vector>

#include "shared/solve/coarse_space.hpp"
#include "shared/solve/dirichlet_dofs.hpp"
#include "shared/solve/explicit_mass.hpp"
#include "shared/solve/linear_solver.hpp"

namespace altfem {

/// Whether two compressed matrices store the same entries (sizes and index arrays equal).
inline bool same_pattern(const Eigen::SparseMatrix<double>& a, const Eigen::SparseMatrix<double>& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() && a.nonZeros() == b.nonZeros() && a.isCompressed() &&
         b.isCompressed() && std::equal(a.outerIndexPtr(), a.outerIndexPtr() + a.outerSize() + 1, b.outerIndexPtr()) &&
         std::equal(a.innerIndexPtr(), a.innerIndexPtr() + a.nonZeros(), b.innerIndexPtr());
}

class Discretization {
public:
  virtual ~Discretization() = default;

  virtual int dof_count() const = 0;

  /// Elastic energy Ψ(u), including any term a method adds (DG face terms, ghost
  /// penalties, weakly imposed conditions); +∞ for a deformation a material rejects.
  virtual double energy(const Eigen::VectorXd& displacement) const = 0;
  /// ∂Ψ/∂u (#dofs).
  virtual void gradient(const Eigen::VectorXd& displacement, Eigen::VectorXd& gradient) const = 0;
  /// ∂²Ψ/∂u² into a matrix with hessian_pattern().
  virtual void hessian(const Eigen::VectorXd& displacement, Eigen::SparseMatrix<double>& hessian,
                       bool project_spd) const = 0;
  /// The sparsity of hessian(), mass_matrix() and every matrix the integrators build
  /// (the default add_mass adds value arrays and refuses a mass of another pattern).
  virtual const Eigen::SparseMatrix<double>& hessian_pattern() const = 0;
  /// Over several ranks with ranks::shares_matrices(), a discretization that divides its
  /// elements among the ranks may give from hessian(), mass_matrix() and add_mass() only
  /// this rank's share of the sum (its own elements' and faces' terms), on a pattern of its
  /// own (hessian_pattern(): those blocks and every function's diagonal block); the
  /// solver sums the shares. Then this is the rank owning each basis function's rows
  /// (#dofs / 3); empty (the default) when every matrix is the whole on every rank.
  /// Vectors and scalars (energy, gradient, mass_times, loads) are always the whole.
  virtual const std::vector<int>& matrix_share_owners() const {
    static const std::vector<int> whole;
    return whole;
  }
  /// True when the Hessian does not depend on u (linear elasticity).
  virtual bool hessian_is_constant() const = 0;
  /// False for a force model whose gradient() is not the derivative of energy() (DG
  /// stiffness warping, Kaufmann et al. 2009 §6): Newton then judges its steps by the
  /// residual instead of the energy, and L-BFGS (which needs a potential) is refused.
  virtual bool forces_have_potential() const { return true; }

  /// Consistent mass matrix, with hessian_pattern().
  virtual const Eigen::SparseMatrix<double>& mass_matrix() const = 0;
  /// M v: what the implicit integrators take of the mass, besides add_mass(). A method
  /// whose mass is much sparser than its Hessian (dg's element blocks) overrides both, so
  /// that no copy of the mass on the Hessian's pattern is built.
  virtual Eigen::VectorXd mass_times(const Eigen::VectorXd& vector) const { return mass_matrix() * vector; }
  /// matrix += factor M, for a matrix with hessian_pattern(): by default the value arrays
  /// added, which is only right when mass_matrix() has that pattern too.
  virtual void add_mass(double factor, Eigen::SparseMatrix<double>& matrix) const {
    const Eigen::SparseMatrix<double>& mass = mass_matrix();
    if (!same_pattern(mass, matrix))
      throw std::logic_error("Discretization::add_mass: the mass matrix and the Hessian patterns differ");
    Eigen::Map<Eigen::VectorXd>(matrix.valuePtr(), matrix.nonZeros()) +=
        factor * Eigen::Map<const Eigen::VectorXd>(mass.valuePtr(), matrix.nonZeros());
  }
  /// The mass explicit integration multiplies and inverts (lumped for Lagrange bases,
  /// block-diagonal for DG).
  virtual const ExplicitMass& explicit_mass() const = 0;

  /// The load vector of a uniform body acceleration a (#dofs): f_(3b+i) = ∫ ρ a_i φ_b dV.
  /// For a partition-of-unity basis it equals M·(a repeated per basis function); for
  /// monomial, harmonic or cut-cell bases only the integral is right.
  virtual Eigen::VectorXd body_force(const Eigen::Vector3d& acceleration) const = 0;
  /// The body load explicit integration pairs with explicit_mass(), so that a uniform
  /// acceleration accelerates every point uniformly: with a lumped mass that is
  /// M_L·(a repeated per basis function), not the integral (Tet10's corner functions
  /// integrate to negative values); with a consistent (block) mass it is body_force(a).
  virtual Eigen::VectorXd explicit_body_force(const Eigen::Vector3d& acceleration) const {
    return body_force(acceleration);
  }
  /// The time the integrators evaluate energy(), gradient() and hessian() at next: every
  /// integrator calls it before it solves at a new time. A force model whose internal
  /// forces hold time-dependent boundary data reads the data here (DG stiffness warping
  /// rotates the Nitsche terms of a moving condition with the boundary element, Kaufmann
  /// et al. 2009 §6). Nothing by default.
  virtual void set_time(double /*time*/) const {}
  /// External forces other than body forces at a time (tractions; the boundary data
  /// of weakly imposed conditions). Zero by default.
  virtual Eigen::VectorXd external_force(double /*time*/) const { return Eigen::VectorXd::Zero(dof_count()); }

  /// The DOFs with a prescribed displacement (sorted); empty for a method that imposes
  /// its conditions weakly. Fixed for the discretization's life: an event that releases
  /// a condition wraps the discretization (released_conditions.hpp).
  virtual const std::vector<int>& constrained_dofs() const = 0;
  /// Their prescribed displacements at a time, in constrained_dofs() order.
  virtual Eigen::VectorXd prescribed_displacement(double time) const = 0;
  /// Which scene conditions hold each constrained DOF (constrained_dofs() order); empty
  /// when the discretization does not record it (then no condition can be released).
  virtual const std::vector<ConstraintHolders>& constraint_holders() const {
    static const std::vector<ConstraintHolders> unrecorded;
    return unrecorded;
  }
  /// True when Dirichlet conditions act inside energy() and external_force() (weakly),
  /// so the problem can be supported with no constrained DOF.
  virtual bool imposes_conditions_weakly() const { return false; }

  /// A method-specific preconditioner for the iterative linear solvers (FCM's
  /// Additive Schwarz, DG's block Jacobi); empty for none.
  virtual PreconditionerFactory preconditioner_factory() const { return {}; }
  /// A coarser space inside this one for multigrid's coarse level (fem's and fcm's
  /// first-order space on higher-order elements); empty for none.
  virtual const CoarseSpace& coarse_space() const {
    static const CoarseSpace none;
    return none;
  }
  /// Per element the Cauchy stress averaged over it (#elements × 9, row-major σ), in
  /// the order of the method's volume cells; empty when the discretization has none.
  virtual Eigen::MatrixXd element_cauchy_stress(const Eigen::VectorXd& /*displacement*/) const { return {}; }
};

}  // namespace altfem
