#include "shared/solve/linear_solver.hpp"

#include "shared/solve/blas_threads.hpp"
#include "shared/solve/cholmod_solver.hpp"
#include "shared/solve/iterative_solver.hpp"
#include "shared/solve/lu_solver.hpp"
#include "shared/solve/petsc_solver.hpp"

#include <chrono>
#include <cstdint>
#include <stdexcept>

namespace altfem {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void require_square(const Eigen::SparseMatrix<double>& matrix) {
  if (matrix.rows() != matrix.cols())
    throw std::logic_error("linear solver: matrix is " + std::to_string(matrix.rows()) + " × " +
                           std::to_string(matrix.cols()) + ", expected a square matrix");
}

// Assembly follows whatever a solver did with BLAS: see blas_threads.hpp. Only the outermost
// factorize() or solve() parks: one nested in another (a two-level preconditioner's coarse
// CHOLMOD solve, every PCG iteration) leaves the threads to the next BLAS call, since
// re-creating them each time made a 22-iteration PCG solve of bench_dg_table1 (12k DOFs,
// 4k coarse) take 7.1 s instead of 0.11 s on a loaded machine.
struct ParkBlasThreadsOnExit {
  ParkBlasThreadsOnExit() { ++depth; }
  ParkBlasThreadsOnExit(const ParkBlasThreadsOnExit&) = delete;
  ParkBlasThreadsOnExit& operator=(const ParkBlasThreadsOnExit&) = delete;
  ~ParkBlasThreadsOnExit() {
    if (--depth == 0) park_blas_threads();
  }
  static thread_local int depth;
};
thread_local int ParkBlasThreadsOnExit::depth = 0;

// FNV-1a over each column's row indices and its end: one number per sparsity pattern.
std::uint64_t pattern_hash(const Eigen::SparseMatrix<double>& matrix) {
  std::uint64_t hash = 1469598103934665603ull;
  const auto mix = [&hash](std::uint64_t value) { hash = (hash ^ value) * 1099511628211ull; };
  for (Eigen::Index column = 0; column < matrix.outerSize(); ++column) {
    for (Eigen::SparseMatrix<double>::InnerIterator entry(matrix, column); entry; ++entry)
      mix(static_cast<std::uint64_t>(entry.row()));
    mix(~static_cast<std::uint64_t>(column));
  }
  return hash;
}

}  // namespace

std::string_view linear_solver_kind_name(LinearSolverKind kind) {
  return linear_solver_kind_names[static_cast<std::size_t>(kind)];
}

std::optional<LinearSolverKind> linear_solver_kind_from_name(std::string_view name) {
  for (std::size_t index = 0; index < linear_solver_kind_names.size(); ++index)
    if (linear_solver_kind_names[index] == name) return static_cast<LinearSolverKind>(index);
  return std::nullopt;
}

bool LinearSolver::has_analysed_pattern(const Eigen::SparseMatrix<double>& matrix) const {
  if (!analysed_ || pattern_columns_ != matrix.cols()) return false;
  if (!analyses_pattern()) return pattern_hash_ == pattern_hash(matrix);
  for (Eigen::Index column = 0; column < matrix.outerSize(); ++column) {
    int position = pattern_column_starts_[column];
    for (Eigen::SparseMatrix<double>::InnerIterator entry(matrix, column); entry; ++entry, ++position)
      if (position >= pattern_column_starts_[column + 1] || pattern_rows_[position] != entry.row()) return false;
    if (position != pattern_column_starts_[column + 1]) return false;
  }
  return true;
}

void LinearSolver::analyze(const Eigen::SparseMatrix<double>& matrix) {
  require_square(matrix);
  const auto start = std::chrono::steady_clock::now();
  analysed_ = false;
  factorised_ = false;
  analyze_pattern(matrix);
  pattern_columns_ = matrix.cols();
  pattern_column_starts_.assign(1, 0);
  pattern_rows_.clear();
  if (analyses_pattern()) {
    // Reserved, not grown: a million-DOF pattern copied at every doubling cost seconds of
    // fresh pages.
    pattern_rows_.reserve(static_cast<size_t>(matrix.nonZeros()));
    pattern_column_starts_.reserve(static_cast<size_t>(matrix.outerSize()) + 1);
    for (Eigen::Index column = 0; column < matrix.outerSize(); ++column) {
      for (Eigen::SparseMatrix<double>::InnerIterator entry(matrix, column); entry; ++entry)
        pattern_rows_.push_back(static_cast<int>(entry.row()));
      pattern_column_starts_.push_back(static_cast<int>(pattern_rows_.size()));
    }
  } else {
    pattern_hash_ = pattern_hash(matrix);
  }
  analysed_ = true;
  ++statistics_.analyses;
  statistics_.analysis_seconds += seconds_since(start);
}

void LinearSolver::factorize(const Eigen::SparseMatrix<double>& matrix) {
  if (!analysed_everywhere(has_analysed_pattern(matrix))) analyze(matrix);
  const ParkBlasThreadsOnExit parking;
  const auto start = std::chrono::steady_clock::now();
  factorised_ = false;
  factorize_values(matrix);
  factorised_ = true;
  ++statistics_.factorisations;
  statistics_.factorisation_seconds += seconds_since(start);
}

void LinearSolver::solve(const Eigen::VectorXd& rhs, Eigen::VectorXd& solution) {
  if (!factorised_) throw std::logic_error("linear solver: solve() called before a successful factorize()");
  if (rhs.size() != pattern_columns_)
    throw std::logic_error("linear solver: right-hand side has " + std::to_string(rhs.size()) +
                           " entries, the matrix " + std::to_string(pattern_columns_) + " columns");
  const ParkBlasThreadsOnExit parking;
  const auto start = std::chrono::steady_clock::now();
  const long iterations = solve_system(rhs, solution);
  ++statistics_.solves;
  statistics_.iterations += iterations;
  statistics_.solve_seconds += seconds_since(start);
}

std::unique_ptr<LinearSolver> make_linear_solver(const LinearSolverOptions& options) {
  switch (options.kind) {
    case LinearSolverKind::cholmod: return make_cholmod_solver(CholmodFactorisation::supernodal_llt);
    case LinearSolverKind::ldlt: return make_cholmod_solver(CholmodFactorisation::simplicial_ldlt);
    case LinearSolverKind::lu: return make_lu_solver();
    case LinearSolverKind::petsc: return make_petsc_solver(options);
    case LinearSolverKind::pcg:
    case LinearSolverKind::minres:
    case LinearSolverKind::conjugate_residual: {
      std::unique_ptr<Preconditioner> preconditioner =
          options.custom_preconditioner ? options.custom_preconditioner() : make_preconditioner(options.preconditioner);
      return make_iterative_solver(options.kind, std::move(preconditioner),
                                   KrylovSettings{options.tolerance, options.max_iterations});
    }
  }
  throw std::logic_error("make_linear_solver: unknown LinearSolverKind");
}

}  // namespace altfem
