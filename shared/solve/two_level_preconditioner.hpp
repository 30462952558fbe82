#pragma once
// A two-level preconditioner: a fine smoother S (any Preconditioner, e.g. block Jacobi)
// and a coarse space given by a prolongation P (#fine × #coarse) with the Galerkin
// coarse operator A_c = Pᵀ A P, factorised by CHOLMOD. After Dobrev, Lazarov, Vassilevski
// & Zikatanov 2006, "Two-level preconditioning of discontinuous Galerkin approximations of
// second-order elliptic equations" (Numer. Linear Algebra Appl. 13): with the continuous
// piecewise-linear functions of the same mesh as coarse space and a (block) Jacobi or
// Gauss–Seidel smoother, the condition number of M⁻¹A is bounded independently of h
// (their §3–4), so PCG's iterations stay bounded under refinement.
//   additive        M⁻¹ = ω S + P A_c⁻¹ Pᵀ
//   multiplicative  one symmetric two-grid V-cycle: pre-smooth x₁ = ω S r, coarse correction
//                   x₂ = x₁ + P A_c⁻¹ Pᵀ (r − A x₁), post-smooth M⁻¹r = x₂ + ω Sᵀ (r − A x₂)
//                   (Sᵀ: Preconditioner::apply_transpose, a Gauss–Seidel sweep run backwards).
//                   Symmetric; positive definite when ‖I − ωSA‖_A < 1, which the damping ω
//                   ensures (block Jacobi on DG: ω ≤ 2/λ_max(SA); Gauss–Seidel: ω = 1).
// P may have linearly dependent columns (a vertex coarse space on hexahedra cannot see the
// hourglass fields, whose per-element affine fits vanish): A_c is then only semidefinite and
// is factorised as A_c + δ diag(A_c), δ = 1e-10. On range(Pᵀ) this is A_c's pseudo-inverse to
// O(δ), and P A_c⁻¹ Pᵀ never sees the kernel, so the correction stays the Galerkin one.
// A coarse preconditioner, when given, replaces the factorisation: A_c⁻¹ becomes its M_c⁻¹,
// and a TwoLevelPreconditioner as M_c makes the cycle a multilevel V-cycle (symmetric
// positive definite when every level's is, so PCG may use it: Bramble, Pasciak & Xu 1991).
#include <memory>

#include "shared/solve/linear_solver.hpp"

namespace altfem {

enum class TwoLevelCycle { additive, multiplicative };

class TwoLevelPreconditioner final : public Preconditioner {
public:
  /// smoother: the fine-level S (computed by compute(); symmetric for the additive cycle);
  /// prolongation: #fine × #coarse; damping: ω above.
  /// coarse: M_c above (computed from A_c by compute()); null: CHOLMOD's factorisation of A_c.
  TwoLevelPreconditioner(std::unique_ptr<Preconditioner> smoother, Eigen::SparseMatrix<double> prolongation,
                         TwoLevelCycle cycle, double damping = 1, std::unique_ptr<Preconditioner> coarse = nullptr);
  ~TwoLevelPreconditioner() override;

  /// Computes S, forms A_c = Pᵀ A P and factorises it (or computes M_c from it). The
  /// multiplicative cycle applies `matrix` in apply(): it must stay alive and unchanged until
  /// the next compute() (the iterative solvers keep their own copy). Throws NumericalError
  /// when A_c is not positive definite (an indefinite A).
  void compute(const Eigen::SparseMatrix<double>& matrix) override;
  void apply(const Eigen::VectorXd& residual, Eigen::VectorXd& result) const override;

  int coarse_size() const { return static_cast<int>(prolongation_.cols()); }
  /// Wall seconds of the last compute()'s smoother set-up and Galerkin product.
  double smoother_seconds() const { return smoother_seconds_; }
  double galerkin_seconds() const { return galerkin_seconds_; }
  /// The coarse CHOLMOD solver's analyses, factorisations and solves so far, and its factor's
  /// size and flops (all zero with a coarse preconditioner, which replaces it).
  const LinearSolverStatistics& coarse_statistics() const;

private:
  void solve_coarse() const;  // coarse_correction_ = A_c⁻¹ (or M_c⁻¹) coarse_residual_

  std::unique_ptr<Preconditioner> smoother_;
  Eigen::SparseMatrix<double> prolongation_, restriction_;  // P and Pᵀ (stored, for fast products)
  TwoLevelCycle cycle_;
  double damping_;
  const Eigen::SparseMatrix<double>* matrix_ = nullptr;
  Eigen::SparseMatrix<double> coarse_matrix_;  // A_c: a coarse preconditioner's cycle applies it
  std::unique_ptr<Preconditioner> coarse_preconditioner_;
  std::unique_ptr<LinearSolver> coarse_solver_;  // CHOLMOD, only without a coarse preconditioner
  double smoother_seconds_ = 0, galerkin_seconds_ = 0;
  // Scratch of apply(), sized by compute(): apply() must not allocate.
  mutable Eigen::VectorXd coarse_residual_, coarse_correction_, fine_residual_, smoothed_;
};

}  // namespace altfem
