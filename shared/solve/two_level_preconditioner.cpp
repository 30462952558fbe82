#include "shared/solve/two_level_preconditioner.hpp"

#include <chrono>
#include <string>

#include "shared/common/error.hpp"
#include "shared/solve/cholmod_solver.hpp"
#include "shared/solve/galerkin_product.hpp"
#include "shared/solve/krylov.hpp"

namespace altfem {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// δ of the shift A_c + δ diag(A_c) (header): far above the rounding of an exactly singular
// A_c's kernel (~1e-16 relative), far below anything that changes the correction elsewhere.
constexpr double coarse_shift = 1e-10;

}  // namespace

TwoLevelPreconditioner::TwoLevelPreconditioner(std::unique_ptr<Preconditioner> smoother,
                                               Eigen::SparseMatrix<double> prolongation, TwoLevelCycle cycle,
                                               double damping, std::unique_ptr<Preconditioner> coarse)
    : smoother_(std::move(smoother)),
      prolongation_(std::move(prolongation)),
      restriction_(prolongation_.transpose()),
      cycle_(cycle),
      damping_(damping),
      coarse_preconditioner_(std::move(coarse)) {
  if (!coarse_preconditioner_) coarse_solver_ = make_cholmod_solver(CholmodFactorisation::supernodal_llt);
  if (cycle_ == TwoLevelCycle::additive && !smoother_->symmetric())
    throw std::logic_error("two-level preconditioner: the additive cycle needs a symmetric smoother");
  if (coarse_preconditioner_ && !coarse_preconditioner_->symmetric())
    throw std::logic_error("two-level preconditioner: the coarse preconditioner must be symmetric");
}

TwoLevelPreconditioner::~TwoLevelPreconditioner() = default;

void TwoLevelPreconditioner::compute(const Eigen::SparseMatrix<double>& matrix) {
  if (matrix.rows() != prolongation_.rows())
    throw std::logic_error("two-level preconditioner: matrix has " + std::to_string(matrix.rows()) +
                           " rows, the prolongation " + std::to_string(prolongation_.rows()));
  matrix_ = &matrix;
  auto start = std::chrono::steady_clock::now();
  smoother_->compute(matrix);
  smoother_seconds_ = seconds_since(start);

  start = std::chrono::steady_clock::now();
  Eigen::SparseMatrix<double>& coarse = coarse_matrix_;
  coarse = galerkin_product(matrix, prolongation_, restriction_);
  // A coarse function P e_j that is zero (a vertex of no element) has a zero row: shift it by
  // the largest diagonal entry so that the kernel is always lifted.
  const Eigen::VectorXd diagonal = coarse.diagonal();
  const double largest = diagonal.size() > 0 ? diagonal.maxCoeff() : 0.0;
  for (Eigen::Index j = 0; j < coarse.cols(); ++j)
    coarse.coeffRef(j, j) += coarse_shift * (diagonal[j] > 0 ? diagonal[j] : largest);
  galerkin_seconds_ = seconds_since(start);

  if (coarse_preconditioner_) {
    coarse_preconditioner_->compute(coarse);
  } else {
    try {
      coarse_solver_->factorize(coarse);
    } catch (const NumericalError& error) {
      throw NumericalError(std::string("two-level preconditioner: the coarse matrix PᵀAP is not positive definite (") +
                           error.what() + ")");
    }
  }

  coarse_residual_.resize(prolongation_.cols());
  coarse_correction_.resize(prolongation_.cols());
  fine_residual_.resize(prolongation_.rows());
  smoothed_.resize(prolongation_.rows());
}

const LinearSolverStatistics& TwoLevelPreconditioner::coarse_statistics() const {
  static const LinearSolverStatistics none;
  return coarse_solver_ ? coarse_solver_->statistics() : none;
}

void TwoLevelPreconditioner::solve_coarse() const {
  if (coarse_preconditioner_) coarse_preconditioner_->apply(coarse_residual_, coarse_correction_);
  else coarse_solver_->solve(coarse_residual_, coarse_correction_);
}

void TwoLevelPreconditioner::apply(const Eigen::VectorXd& residual, Eigen::VectorXd& result) const {
  // The pre-smoothed defect r − A x₁: from the smoother itself when it can (undamped
  // Gauss–Seidel keeps it current as it sweeps), else by a product with A below.
  const bool have_defect = cycle_ == TwoLevelCycle::multiplicative && damping_ == 1 &&
                           smoother_->apply_with_defect(residual, result, fine_residual_);
  if (!have_defect) {
    smoother_->apply(residual, result);
    result *= damping_;
  }
  if (cycle_ == TwoLevelCycle::additive) {
    coarse_residual_.noalias() = restriction_ * residual;
    solve_coarse();
    result.noalias() += prolongation_ * coarse_correction_;
    return;
  }
  // The symmetric V-cycle: pre-smoothed above, coarse correction of the remaining residual,
  // post-smoothing with ω Sᵀ (S itself for a symmetric smoother).
  if (!have_defect) {
    symmetric_multiply(*matrix_, result, fine_residual_);
    fine_residual_ = residual - fine_residual_;
  }
  coarse_residual_.noalias() = restriction_ * fine_residual_;
  solve_coarse();
  result.noalias() += prolongation_ * coarse_correction_;
  symmetric_multiply(*matrix_, result, fine_residual_);
  fine_residual_ = residual - fine_residual_;
  smoother_->apply_transpose(fine_residual_, smoothed_);
  result += damping_ * smoothed_;
}

}  // namespace altfem
