#pragma once
// The preconditioner interface of the Krylov solvers. Eigen's iterative solvers
// take their preconditioner as a compile-time template parameter; altfem chooses
// it at run time (from the scene, or a method-specific one such as FCM's Additive
// Schwarz), hence this small virtual interface and our own Krylov loops.
#include <Eigen/Sparse>

#include <array>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string_view>

namespace altfem {

/// An approximation M ≈ A whose inverse is cheap to apply. Krylov methods for
/// symmetric systems (PCG, MINRES, conjugate residual) need M symmetric positive
/// definite.
class Preconditioner {
public:
  virtual ~Preconditioner() = default;
  /// Sets up from `matrix` (#dofs × #dofs, symmetric, both triangles stored);
  /// called after every change of the matrix values.
  virtual void compute(const Eigen::SparseMatrix<double>& matrix) = 0;
  /// result = M⁻¹ · residual (both #dofs). Called every Krylov iteration, so it
  /// must not allocate; `result` never aliases `residual`.
  virtual void apply(const Eigen::VectorXd& residual, Eigen::VectorXd& result) const = 0;
  /// Whether M is symmetric: every preconditioner but a one-way smoothing sweep. PCG and
  /// additive cycles need a symmetric one.
  virtual bool symmetric() const { return true; }
  /// A value the largest eigenvalue of M⁻¹A is known to reach from M's structure alone
  /// (0: nothing known), so that a smoother's bounds cover modes a Krylov estimate from a
  /// random start can miss.
  virtual double largest_eigenvalue_at_least() const { return 0; }
  /// Whether compute_from_shares() is available.
  virtual bool computes_from_shares() const { return false; }
  /// Over several ranks, sets up from this rank's share of the matrix, the whole being the
  /// sum of every rank's share (a solver that sums shares, PETSc: docs/scaling.md), so that
  /// apply() then acts on whole vectors alike on every rank. Collective: every rank calls it.
  virtual void compute_from_shares(const Eigen::SparseMatrix<double>& /*share*/) {
    throw std::logic_error("this preconditioner cannot be set up from the ranks' shares of a matrix");
  }
  /// result = M⁻ᵀ · residual: the post-smoothing of a symmetric V-cycle whose pre-smoothing
  /// is apply() (a Gauss–Seidel sweep run backwards); apply() itself when M is symmetric.
  virtual void apply_transpose(const Eigen::VectorXd& residual, Eigen::VectorXd& result) const {
    apply(residual, result);
  }
  /// result = M⁻¹ · residual and defect = residual − A · result (A: the matrix of the last
  /// compute()) when the preconditioner obtains the defect as it goes (a Gauss–Seidel sweep
  /// updating it block by block), saving a cycle's product with A; false, writing nothing,
  /// when it does not.
  virtual bool apply_with_defect(const Eigen::VectorXd& /*residual*/, Eigen::VectorXd& /*result*/,
                                 Eigen::VectorXd& /*defect*/) const {
    return false;
  }
};

/// Makes a fresh preconditioner for each solver that needs one (method-specific
/// preconditioners are plugged in this way).
using PreconditionerFactory = std::function<std::unique_ptr<Preconditioner>()>;

/// M = I: the unpreconditioned method.
class IdentityPreconditioner final : public Preconditioner {
public:
  void compute(const Eigen::SparseMatrix<double>&) override {}
  void apply(const Eigen::VectorXd& residual, Eigen::VectorXd& result) const override { result = residual; }
};

/// The names accepted by make_preconditioner (scene key solver.preconditioner).
inline constexpr std::array<std::string_view, 3> preconditioner_names{"none", "jacobi", "incomplete_cholesky"};

/// The preconditioner called `name` (one of preconditioner_names); throws
/// InputError for any other name.
std::unique_ptr<Preconditioner> make_preconditioner(std::string_view name);

}  // namespace altfem
