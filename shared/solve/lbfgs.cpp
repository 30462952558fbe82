#include "shared/solve/lbfgs.hpp"

#include <nlopt.hpp>

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <stdexcept>
#include <vector>

namespace altfem {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

// Luksan's L-BFGS (NLopt's LD_LBFGS) has a hard-coded stop ‖∇f‖∞ ≤ 1e-8
// (luksan/plis.c, tolg). Handing NLopt s·f with s ≥ √n · 1e-8 / (tolerance · c) makes
// that test imply ours, ‖∇f‖₂ ≤ √n ‖∇f‖∞ ≤ tolerance, so ours always decides; c is the
// smallest variable scale, since NLopt sees the gradient in y, scale ⊙ ∇f.
double objective_scale(Eigen::Index size, double gradient_tolerance, double smallest_variable_scale) {
  return std::max(1.0, 2 * std::sqrt(static_cast<double>(size)) * 1e-8 / (gradient_tolerance * smallest_variable_scale));
}

struct Run {
  const LbfgsObjective& objective;
  nlopt::opt& optimizer;
  double gradient_tolerance = 0;
  int max_evaluations = 0;
  double scale = 1;
  const Eigen::VectorXd* variable_scale = nullptr;  // x = variable_scale ⊙ y, or null
  Eigen::VectorXd point{}, gradient{};  // workspaces, #unknowns
  Eigen::VectorXd best_point{};
  double best_value = infinity;
  double best_gradient_norm = infinity;
  int evaluations = 0;
  bool converged = false;
  bool out_of_evaluations = false;
  std::exception_ptr error{};

  bool stopping() const { return converged || out_of_evaluations || error; }
};

double evaluate(unsigned size, const double* x, double* gradient, void* data) {
  Run& run = *static_cast<Run*>(data);
  // NLopt only looks at force_stop() between line searches; until it does, the
  // line search gets +inf without the objective being evaluated.
  if (run.stopping()) {
    if (gradient != nullptr) std::fill(gradient, gradient + size, 0.0);
    return infinity;
  }
  try {
    run.point = Eigen::Map<const Eigen::VectorXd>(x, size);
    if (run.variable_scale) run.point = run.point.cwiseProduct(*run.variable_scale);
    const double value = run.objective(run.point, run.gradient);
    ++run.evaluations;
    if (run.gradient.size() != static_cast<Eigen::Index>(size))
      throw std::logic_error("minimize_lbfgs: the objective wrote a gradient of the wrong size");
    if (gradient != nullptr) {
      Eigen::Map<Eigen::VectorXd> output(gradient, size);
      output = run.scale * run.gradient;
      if (run.variable_scale) output = output.cwiseProduct(*run.variable_scale);  // ∇_y f = scale ⊙ ∇_x f
    }
    if (run.evaluations >= run.max_evaluations) run.out_of_evaluations = true;
    if (std::isfinite(value)) {
      const double gradient_norm = run.gradient.norm();
      run.converged = gradient_norm <= run.gradient_tolerance;
      if (value < run.best_value || run.converged) {
        run.best_value = value;
        run.best_point = run.point;
        run.best_gradient_norm = gradient_norm;
      }
    }
    if (run.stopping()) run.optimizer.force_stop();
    return run.scale * value;
  } catch (...) {
    // Exceptions must not cross NLopt's C code; nlopt.hpp would turn them into a bare "nlopt failure".
    run.error = std::current_exception();
    run.optimizer.force_stop();
    return infinity;
  }
}

}  // namespace

LbfgsResult minimize_lbfgs(const LbfgsObjective& objective, Eigen::VectorXd& x, const LbfgsOptions& options) {
  nlopt::opt optimizer(nlopt::LD_LBFGS, static_cast<unsigned>(x.size()));
  Run run{.objective = objective,
          .optimizer = optimizer,
          .gradient_tolerance = options.gradient_tolerance,
          .max_evaluations = options.max_evaluations,
          .scale = objective_scale(x.size(), options.gradient_tolerance,
                                   options.scale.size() > 0 ? options.scale.minCoeff() : 1.0),
          .variable_scale = options.scale.size() > 0 ? &options.scale : nullptr,
          .best_point = x};
  if (run.variable_scale && (run.variable_scale->size() != x.size() || !(run.variable_scale->array() > 0).all()))
    throw std::invalid_argument("minimize_lbfgs: the variable scale must be positive, one entry per unknown");
  optimizer.set_min_objective(evaluate, &run);
  optimizer.set_vector_storage(static_cast<unsigned>(std::max(options.memory, 1)));
  // Luksan's code replaces tolerances ≤ 0 by its defaults (ftol 1e-14 relative,
  // xtol 1e-16), which stop it before small gradients are reached; the smallest
  // positive tolerance leaves only exact stagnation.
  optimizer.set_ftol_rel(std::numeric_limits<double>::min());
  optimizer.set_xtol_rel(std::numeric_limits<double>::min());

  std::vector<double> point(x.data(), x.data() + x.size());
  if (run.variable_scale)
    for (Eigen::Index i = 0; i < x.size(); ++i) point[i] /= (*run.variable_scale)[i];
  double value = 0;
  nlopt::result code = nlopt::FAILURE;
  try {
    code = optimizer.optimize(point, value);
  } catch (const nlopt::forced_stop&) {
    code = nlopt::FORCED_STOP;
  } catch (const nlopt::roundoff_limited&) {
    code = nlopt::ROUNDOFF_LIMITED;
  } catch (const std::runtime_error&) {  // NLOPT_FAILURE, e.g. a line search that found no decrease
    code = nlopt::FAILURE;
  }
  if (run.error) std::rethrow_exception(run.error);

  LbfgsResult result;
  result.evaluations = run.evaluations;
  result.detail = nlopt_result_to_string(static_cast<nlopt_result>(code));
  result.status = run.converged            ? LbfgsStatus::converged
                  : run.out_of_evaluations ? LbfgsStatus::max_evaluations
                                           : LbfgsStatus::stalled;
  x = run.best_point;
  result.objective = run.best_value;
  result.gradient_norm = run.best_gradient_norm;
  return result;
}

}  // namespace altfem
