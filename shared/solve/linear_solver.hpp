#pragma once
// Sparse linear solvers behind one interface. Direct: CHOLMOD supernodal LLᵀ
// (the default, SPD), CHOLMOD simplicial LDLᵀ (quasi-definite indefinite) and
// UMFPACK LU (general). Iterative: PCG, MINRES and conjugate residual with a
// run-time preconditioner, and PETSc's Krylov solvers and preconditioners (petsc_solver.hpp). Symbolic analysis happens
// once per sparsity pattern and is reused across Newton iterations and time steps; the statistics feed summary.json
// (timings_s.analysis, timings_s.factorisation, counts.*).
#include "shared/solve/coarse_space.hpp"
#include "shared/solve/preconditioner.hpp"

#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace altfem {

/// What a solver has done so far. Times are wall seconds (monotonic clock).
struct LinearSolverStatistics {
  int analyses = 0;        ///< symbolic analyses (one per distinct sparsity pattern)
  int factorisations = 0;  ///< numeric factorisations (direct) / preconditioner set-ups (iterative)
  int solves = 0;
  long iterations = 0;  ///< Krylov iterations summed over all solves (0 for direct solvers)
  double analysis_seconds = 0;
  double factorisation_seconds = 0;
  double solve_seconds = 0;
  /// Direct solvers, from the last analysis: entries of the factor L (without the
  /// zeros supernodal amalgamation adds) and floating-point operations of one
  /// factorisation (0 when unknown, and for iterative solvers).
  double factor_entries = 0;
  double factorisation_flops = 0;
  /// Direct solvers: the fewest and the most BLAS threads a factorisation got
  /// (blas_thread_choice.hpp); 0 before the first, and for solvers without BLAS.
  int fewest_blas_threads = 0;
  int most_blas_threads = 0;
};

enum class LinearSolverKind { cholmod, ldlt, lu, pcg, minres, conjugate_residual, petsc };

/// Scene names of the kinds, indexed by the enum value.
inline constexpr std::array<std::string_view, 7> linear_solver_kind_names{
    "cholmod", "ldlt", "lu", "pcg", "minres", "conjugate_residual", "petsc"};

std::string_view linear_solver_kind_name(LinearSolverKind kind);
/// A Krylov method (no factor, a preconditioner), not a direct factorisation; `petsc`
/// counts as one, its default being CG + GAMG.
constexpr bool is_iterative(LinearSolverKind kind) {
  return kind == LinearSolverKind::pcg || kind == LinearSolverKind::minres ||
         kind == LinearSolverKind::conjugate_residual || kind == LinearSolverKind::petsc;
}
/// The kind called `name` (one of linear_solver_kind_names), or nothing.
std::optional<LinearSolverKind> linear_solver_kind_from_name(std::string_view name);

struct LinearSolverOptions {
  LinearSolverKind kind = LinearSolverKind::cholmod;
  /// Iterative solvers only: one of preconditioner_names.
  std::string preconditioner = "jacobi";
  /// Iterative solvers only: when set, replaces `preconditioner` (e.g. FCM's Additive Schwarz).
  PreconditionerFactory custom_preconditioner;
  /// Iterative solvers: stop when ‖b − A x‖₂ ≤ tolerance · ‖b‖₂.
  double tolerance = 1e-10;
  int max_iterations = 10000;
  /// `petsc` only: PETSc options (e.g. "-ksp_type cg -pc_type gamg"), applied after
  /// `tolerance` and `max_iterations`, so they may override both.
  std::string petsc_options;
  /// `petsc` only: a basis of the near-null space of the operator without its Dirichlet
  /// conditions (#dofs × 6: the rigid-body modes, DOF 3b + i being component i of basis
  /// function b), which smoothed-aggregation AMG builds its coarse spaces from; empty for none.
  Eigen::MatrixXd near_null_space;
  /// `petsc`: `custom_preconditioner` (a method's own: FCM's Additive Schwarz, dg's) as the
  /// smoother of multigrid's finest level (petsc_finest_smoother.hpp); over several ranks
  /// only one that can be set up from the ranks' shares (Preconditioner::compute_from_shares).
  bool method_smoother = true;
  /// `petsc`, when its preconditioner is GAMG: a coarser space of the
  /// method (Discretization::coarse_space) on which GAMG works as the coarse level of a
  /// two-level multigrid, the method's own space its fine level (petsc_coarse_level.hpp);
  /// empty: GAMG on the whole.
  CoarseSpace coarse_space;
  /// `petsc`, where its preconditioner is GAMG (the coarse level's included): coarsen the
  /// finest level aggressively (PETSc's default, MIS-2 on the squared graph), a cheaper
  /// set-up for more iterations; false where one set-up serves many solves
  /// (linear_solver_options). `petsc_options` may still choose.
  bool aggressive_coarsening = true;
  /// `petsc` over several ranks: when the matrices handed over are each rank's share of a
  /// sum on a pattern of its own (Discretization::matrix_share_owners), the rank owning
  /// each block of three rows (#dofs / 3); empty when every rank hands over the whole.
  std::vector<int> share_row_owners;
};

/// Solves A x = b for a sparse square A (#dofs × #dofs, column-major; symmetric
/// matrices are stored with both triangles). Usage: analyze(A) once per
/// sparsity pattern, factorize(A) whenever the values change, then solve(b, x)
/// as often as needed.
class LinearSolver {
public:
  virtual ~LinearSolver() = default;

  /// Symbolic analysis of the sparsity pattern of `matrix` (fill-reducing ordering, elimination tree).
  void analyze(const Eigen::SparseMatrix<double>& matrix);
  /// Numeric factorisation of `matrix` (direct) or preconditioner set-up
  /// (iterative). Analyses first when `matrix`'s pattern differs from the
  /// analysed one (or none was analysed), so a changed pattern costs one more
  /// analysis and never a wrong answer. Throws NumericalError when `matrix`
  /// does not suit the solver (e.g. not positive definite for CHOLMOD LLᵀ). An
  /// iterative solver multiplies by `matrix` itself in solve(): it must stay alive and
  /// unchanged until the next factorize() (a direct solver keeps its factor instead).
  void factorize(const Eigen::SparseMatrix<double>& matrix);
  /// solution = A⁻¹ rhs for the last factorised A; rhs and solution are #dofs
  /// and must be different vectors.
  /// Throws NumericalError when an iterative solver does not converge.
  void solve(const Eigen::VectorXd& rhs, Eigen::VectorXd& solution);

  const LinearSolverStatistics& statistics() const { return statistics_; }
  virtual std::string_view name() const = 0;

protected:
  virtual void analyze_pattern(const Eigen::SparseMatrix<double>& matrix) = 0;
  /// Whether analyze_pattern() computes something from the pattern (a fill-reducing
  /// ordering): then the whole pattern is kept to tell a changed one; otherwise a 64-bit
  /// hash of it, which only the statistics' count of analyses depends on (an iterative
  /// solver held a third of a stiffness matrix for nothing, issue #35).
  virtual bool analyses_pattern() const { return true; }
  virtual void factorize_values(const Eigen::SparseMatrix<double>& matrix) = 0;
  /// Whether every process of a solve over several ranks has analysed its pattern, given
  /// whether this one has: such a solver analyses collectively, and the ranks' patterns
  /// (their shares of the matrix) may change on one rank alone.
  virtual bool analysed_everywhere(bool here) const { return here; }
  /// Returns the number of iterations the solve took (0 for a direct solve).
  virtual long solve_system(const Eigen::VectorXd& rhs, Eigen::VectorXd& solution) = 0;
  /// For analyze_pattern of direct solvers: the size of the factor it predicts.
  void record_factor_size(double entries, double flops) {
    statistics_.factor_entries = entries;
    statistics_.factorisation_flops = flops;
  }
  void record_blas_threads(int threads) {
    statistics_.fewest_blas_threads =
        statistics_.fewest_blas_threads == 0 ? threads : std::min(statistics_.fewest_blas_threads, threads);
    statistics_.most_blas_threads = std::max(statistics_.most_blas_threads, threads);
  }

private:
  bool has_analysed_pattern(const Eigen::SparseMatrix<double>& matrix) const;

  LinearSolverStatistics statistics_;
  // The analysed pattern in compressed-column form: column starts (#dofs + 1) and row indices (#nonzeros).
  std::vector<int> pattern_column_starts_;
  std::vector<int> pattern_rows_;
  Eigen::Index pattern_columns_ = 0;
  std::uint64_t pattern_hash_ = 0;  // when !analyses_pattern()
  bool analysed_ = false;
  bool factorised_ = false;
};

/// The solver `options` describe; the preconditioner of an iterative solver is
/// made here. Throws InputError for an unknown preconditioner name.
std::unique_ptr<LinearSolver> make_linear_solver(const LinearSolverOptions& options);

}  // namespace altfem
