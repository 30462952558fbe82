#include "shared/solve/newton.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <span>
#include <string>

#include "shared/common/error.hpp"
#include "shared/solve/process_ranks.hpp"

namespace altfem {

namespace {
std::string scientific(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3e", value);
  return text;
}

std::string where(int step, int iteration) {
  return "step " + std::to_string(step) + ", Newton iteration " + std::to_string(iteration);
}
}  // namespace

void NewtonSolver::assemble_hessian(const Objective& objective, const Eigen::VectorXd& u, bool project_spd, int step,
                                    int iteration) {
  try {
    objective.hessian(u, matrix_, project_spd);
  } catch (const NumericalError& error) {
    throw NumericalError(where(step, iteration) + ": " + error.what());
  }
}

void NewtonSolver::evaluate_gradient(const Objective& objective, const Eigen::VectorXd& u, int step, int iteration) {
  // An inverted element throws from the assembler naming the element; say where.
  try {
    objective.gradient(u, gradient_);
  } catch (const NumericalError& error) {
    throw NumericalError(where(step, iteration) + ": " + error.what());
  }
}

NewtonSolver::NewtonSolver(LinearSolver& linear_solver, const Eigen::SparseMatrix<double>& pattern,
                           const DirichletElimination& elimination, bool matrix_shares)
    : linear_solver_(linear_solver), elimination_(elimination), matrix_(pattern), matrix_shares_(matrix_shares) {}

void NewtonSolver::lift(const Eigen::SparseMatrix<double>& matrix, const Eigen::VectorXd& increment) {
  if (!matrix_shares_ || increment.squaredNorm() == 0) {
    // Without increments the lifting only zeroes the constrained entries: no sum needed.
    elimination_.lift(matrix, rhs_, increment);
    return;
  }
  // r'_f = r_f − K_fc Δc and r'_c = K_cc Δc are linear in K: the shares' liftings, summed.
  lifted_.setZero(rhs_.size());
  elimination_.lift(matrix, lifted_, increment);
  ranks::sum(std::span<double>(lifted_.data(), static_cast<size_t>(lifted_.size())));
  elimination_.set_constrained(rhs_, Eigen::VectorXd::Zero(increment.size()));
  rhs_ += lifted_;
}

void NewtonSolver::solve_step(const Objective& objective, const Eigen::VectorXd& u, const Eigen::VectorXd& gradient,
                              const Eigen::VectorXd& increment, bool project_spd, int step, int iteration) {
  rhs_ = -gradient;
  const bool reuse = objective.hessian_is_constant() && constant_factorised_;
  // The lifting K_fc Δc needs the Hessian before elimination; without constrained DOFs
  // there is none to lift, and no second copy of the Hessian is kept.
  const bool lifts = !elimination_.constrained_dofs().empty();
  if (reuse) {
    if (lifts) lift(constant_hessian_, increment);
  } else {
    assemble_hessian(objective, u, project_spd, step, iteration);
    if (objective.hessian_is_constant() && lifts) constant_hessian_ = matrix_;
    if (lifts) lift(matrix_, increment);
    elimination_.eliminate(matrix_);
    // factorize() analyses the pattern when it differs from the solver's last one: a
    // Newton solver made after an event with an unchanged pattern analyses nothing.
    try {
      linear_solver_.factorize(matrix_);
    } catch (const NumericalError& error) {
      if (project_spd) throw NumericalError(where(step, iteration) + ": " + error.what());
      rhs_ = -gradient;
      assemble_hessian(objective, u, true, step, iteration);
      if (lifts) lift(matrix_, increment);
      elimination_.eliminate(matrix_);
      try {
        linear_solver_.factorize(matrix_);
      } catch (const NumericalError& again) {
        throw NumericalError(where(step, iteration) + ": " + again.what());
      }
    }
    constant_factorised_ = objective.hessian_is_constant();
  }
  try {
    linear_solver_.solve(rhs_, direction_);
  } catch (const NumericalError& error) {
    throw NumericalError(where(step, iteration) + ": " + error.what());
  }
  if (!direction_.allFinite())
    throw NumericalError(where(step, iteration) + ": the linear solve produced non-finite values");
  // An iterative solver meets the constrained rows only to its tolerance (a Schwarz
  // block couples them to free DOFs), and the constraints must be met exactly for
  // Newton to stop: they are known, so set them.
  elimination_.set_constrained(direction_, increment);
}

double NewtonSolver::round_off_floor(const Eigen::VectorXd& u) {
  magnitudes_.setZero(u.size());
  for (Eigen::Index column = 0; column < matrix_.outerSize(); ++column)
    for (Eigen::SparseMatrix<double>::InnerIterator entry(matrix_, column); entry; ++entry)
      magnitudes_[entry.row()] += std::abs(entry.value()) * std::abs(u[column]);
  // Over shares, Σ_ranks |H_r| |u| ≥ |H| |u|: a floor at least one process's.
  if (matrix_shares_) ranks::sum(std::span<double>(magnitudes_.data(), static_cast<size_t>(magnitudes_.size())));
  return 16 * std::numeric_limits<double>::epsilon() * elimination_.free_norm(magnitudes_);
}

NewtonReport NewtonSolver::minimize(const Objective& objective, Eigen::VectorXd& u, const Eigen::VectorXd& prescribed,
                                    const NewtonOptions& options, int step) {
  NewtonReport report;
  iterations_of_last_call_ = 0;
  for (int iteration = 0;; ++iteration) {
    evaluate_gradient(objective, u, step, iteration);
    const Eigen::VectorXd increment = prescribed - elimination_.constrained_values(u);
    const double residual = elimination_.free_norm(gradient_);
    report.residual = residual;
    const bool constraints_met = increment.lpNorm<Eigen::Infinity>() == 0.0;
    if (constraints_met && residual <= options.tolerance) return report;
    // iteration > 0: solve_step has left the eliminated Hessian in matrix_.
    if (constraints_met && iteration > 0 && objective.hessian_is_constant()) {
      const double floor = round_off_floor(u);
      if (residual <= floor) {
        report.round_off_floor = floor;
        return report;
      }
    }
    if (!std::isfinite(residual)) throw NumericalError(where(step, iteration) + ": non-finite residual");
    if (iteration >= options.max_iterations)
      throw NumericalError(where(step, iteration) + ": not converged, residual " + scientific(residual) +
                           " > tolerance " + scientific(options.tolerance));

    solve_step(objective, u, gradient_, increment, options.project_spd, step, iteration);
    ++report.iterations;
    iterations_of_last_call_ = report.iterations;

    // Backtracking: Armijo's sufficient decrease when the constraints are met (the
    // direction is then a descent direction of the free problem); while constraints
    // still move, only finiteness is asked (the prescribed step need not descend).
    const double value = objective.value(u);
    const double slope = gradient_.dot(direction_);
    double alpha = 1.0;
    for (int backtrack = 0;; ++backtrack) {
      trial_ = u + alpha * direction_;
      const double trial_value = objective.value(trial_);
      const bool accepted = !options.line_search || (constraints_met ? trial_value <= value + 1e-4 * alpha * slope
                                                                     : std::isfinite(trial_value));
      if (accepted) break;
      // Near the minimum the decrease Armijo asks for falls below the round-off of the
      // energy (a sum of terms of order μ·V): judge the full step by the gradient
      // instead, and accept it when it halves the residual. A force model's energy is
      // only a merit function (its gradient is not the force), and its tangent may
      // converge linearly: there any step that lowers the residual is taken.
      const bool potential = objective.gradient_has_potential();
      if (constraints_met && (backtrack == 0 || !potential) && std::isfinite(trial_value)) {
        objective.gradient(trial_, trial_gradient_);
        if (elimination_.free_norm(trial_gradient_) <= (potential ? 0.5 : 1.0) * residual) break;
      }
      if (backtrack >= options.max_backtracks)
        throw NumericalError(where(step, iteration) + ": line search failed (no decrease after " +
                             std::to_string(backtrack) + " halvings; " +
                             (objective.hessian_is_constant()
                                  ? "with a constant tangent this means the residual " + scientific(residual) +
                                        " is at the round-off of the linear solve)"
                                  : "an element may be inverted)"));
      alpha *= 0.5;
    }
    u = trial_;
  }
}

NewtonReport NewtonSolver::single_step(const Objective& objective, Eigen::VectorXd& u,
                                       const Eigen::VectorXd& prescribed, const NewtonOptions& options, int step) {
  iterations_of_last_call_ = 0;
  evaluate_gradient(objective, u, step, 0);
  const Eigen::VectorXd increment = prescribed - elimination_.constrained_values(u);
  solve_step(objective, u, gradient_, increment, options.project_spd, step, 0);
  iterations_of_last_call_ = 1;
  u += direction_;
  objective.gradient(u, gradient_);
  return NewtonReport{1, elimination_.free_norm(gradient_)};
}

}  // namespace altfem
