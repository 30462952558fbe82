#pragma once
// What a method gives the time integrators (DESIGN.md, "Core abstractions"). The fem
// method implements it now; fcm, dg and harmonic will.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "shared/solve/linear_solver.hpp"

namespace altfem {

class Discretization {
public:
  virtual ~Discretization() = default;

  virtual int dof_count() const = 0;

  /// Elastic energy Ψ(u); +∞ for a deformation a material rejects.
  virtual double energy(const Eigen::VectorXd& displacement) const = 0;
  /// ∂Ψ/∂u (#dofs).
  virtual void gradient(const Eigen::VectorXd& displacement, Eigen::VectorXd& gradient) const = 0;
  /// ∂²Ψ/∂u² into a matrix with hessian_pattern().
  virtual void hessian(const Eigen::VectorXd& displacement, Eigen::SparseMatrix<double>& hessian,
                       bool project_spd) const = 0;
  /// The sparsity of hessian(), mass_matrix() and every matrix the integrators build.
  virtual const Eigen::SparseMatrix<double>& hessian_pattern() const = 0;
  /// True when the Hessian does not depend on u (linear elasticity).
  virtual bool hessian_is_constant() const = 0;

  /// Consistent mass matrix, with hessian_pattern().
  virtual const Eigen::SparseMatrix<double>& mass_matrix() const = 0;
  /// Diagonal (lumped) mass for explicit integration (#dofs, positive).
  virtual const Eigen::VectorXd& lumped_mass() const = 0;

  /// External forces other than gravity at a time (gravity is M·g, added by the
  /// integrators). Zero by default.
  virtual Eigen::VectorXd external_force(double /*time*/) const { return Eigen::VectorXd::Zero(dof_count()); }

  /// The DOFs with a prescribed displacement (sorted, fixed for the whole run).
  virtual const std::vector<int>& constrained_dofs() const = 0;
  /// Their prescribed displacements at a time, in constrained_dofs() order.
  virtual Eigen::VectorXd prescribed_displacement(double time) const = 0;

  /// A method-specific preconditioner for the iterative linear solvers (FCM's
  /// Additive Schwarz, DG's block Jacobi); empty for none.
  virtual PreconditionerFactory preconditioner_factory() const { return {}; }
};

}  // namespace altfem
