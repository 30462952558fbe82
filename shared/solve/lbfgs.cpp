#include "shared/solve/lbfgs.hpp"

#include <cmath>
#include <deque>
#include <stdexcept>

namespace altfem {
namespace {

// Hager & Zhang's approximate Wolfe conditions (2005, eq. (23)) with δ = 0.1, σ = 0.9,
// and their energy slack ε_k = 1e-6 |f(x)| for values at round-off.
constexpr double sufficient_decrease = 0.1, curvature = 0.9, energy_slack = 1e-6;
constexpr int max_line_search_evaluations = 40;

struct Point {
  Eigen::VectorXd x, gradient;  // gradient in the scaled variables
  double value = 0;
};

class Minimizer {
public:
  Minimizer(const LbfgsObjective& objective, const LbfgsOptions& options, LbfgsResult& result)
      : objective_(objective), options_(options), result_(result) {}

  // f and ∇_y f at y (x = scale ⊙ y), counting evaluations; ‖∇_x f‖ into `norm`.
  Point evaluate(const Eigen::VectorXd& y, double& norm) {
    Point point{y, Eigen::VectorXd(), 0};
    Eigen::VectorXd x = scaled() ? y.cwiseProduct(options_.scale) : y;
    point.value = objective_(x, gradient_);
    ++result_.evaluations;
    if (gradient_.size() != y.size())
      throw std::logic_error("minimize_lbfgs: the objective wrote a gradient of the wrong size");
    norm = gradient_.norm();
    point.gradient = scaled() ? gradient_.cwiseProduct(options_.scale) : gradient_;
    return point;
  }
  bool out_of_evaluations() const { return result_.evaluations >= options_.max_evaluations; }

private:
  bool scaled() const { return options_.scale.size() > 0; }
  const LbfgsObjective& objective_;
  const LbfgsOptions& options_;
  LbfgsResult& result_;
  Eigen::VectorXd gradient_;
};

// −H∇f by the two-loop recursion over the stored pairs (s, y), H₀ = γI.
Eigen::VectorXd direction(const Eigen::VectorXd& gradient,
                          const std::deque<std::pair<Eigen::VectorXd, Eigen::VectorXd>>& pairs) {
  Eigen::VectorXd q = -gradient;
  std::vector<double> alpha(pairs.size());
  for (size_t i = pairs.size(); i-- > 0;) {
    const auto& [s, y] = pairs[i];
    alpha[i] = s.dot(q) / y.dot(s);
    q -= alpha[i] * y;
  }
  if (!pairs.empty()) q *= pairs.back().first.dot(pairs.back().second) / pairs.back().second.squaredNorm();
  for (size_t i = 0; i < pairs.size(); ++i) {
    const auto& [s, y] = pairs[i];
    q += (alpha[i] - y.dot(q) / y.dot(s)) * s;
  }
  return q;
}

}  // namespace

LbfgsResult minimize_lbfgs(const LbfgsObjective& objective, Eigen::VectorXd& x, const LbfgsOptions& options) {
  if (options.scale.size() > 0 && (options.scale.size() != x.size() || !(options.scale.array() > 0).all()))
    throw std::invalid_argument("minimize_lbfgs: the variable scale must be positive, one entry per unknown");
  LbfgsResult result;
  Minimizer minimizer(objective, options, result);
  const Eigen::VectorXd start = options.scale.size() > 0 ? x.cwiseQuotient(options.scale) : x;
  double norm = 0;
  Point current = minimizer.evaluate(start, norm);
  if (!std::isfinite(current.value))
    throw std::invalid_argument("minimize_lbfgs: the objective is not finite at the start");
  std::deque<std::pair<Eigen::VectorXd, Eigen::VectorXd>> pairs;
  const auto finish = [&](LbfgsStatus status, const std::string& detail) {
    result.status = status;
    result.detail = detail;
    result.objective = current.value;
    result.gradient_norm = norm;
    x = options.scale.size() > 0 ? current.x.cwiseProduct(options.scale) : current.x;
    return result;
  };

  for (;;) {
    if (norm <= options.gradient_tolerance) return finish(LbfgsStatus::converged, "converged");
    if (minimizer.out_of_evaluations()) return finish(LbfgsStatus::max_evaluations, "out of evaluations");
    Eigen::VectorXd d = direction(current.gradient, pairs);
    double slope = current.gradient.dot(d);
    if (!(slope < 0)) {  // not a descent direction: restart from steepest descent
      pairs.clear();
      d = -current.gradient;
      slope = current.gradient.dot(d);
    }
    // The first step of a restart is scaled so that it moves at most unit length.
    double step = pairs.empty() ? std::min(1.0, 1.0 / d.lpNorm<Eigen::Infinity>()) : 1.0;
    double low = 0, high = INFINITY;  // bracket of acceptable steps
    Point trial;
    double trial_norm = 0;
    bool accepted = false;
    for (int search = 0; search < max_line_search_evaluations && !minimizer.out_of_evaluations(); ++search) {
      trial = minimizer.evaluate(current.x + step * d, trial_norm);
      const double trial_slope = trial.gradient.dot(d);
      const bool finite = std::isfinite(trial.value) && std::isfinite(trial_slope);
      const bool armijo = finite && trial.value - current.value <= sufficient_decrease * step * slope;
      const bool approximate = finite && trial.value <= current.value + energy_slack * std::abs(current.value) &&
                               trial_slope <= (2 * sufficient_decrease - 1) * slope;
      const bool flat_enough = finite && trial_slope >= curvature * slope;
      if ((armijo || approximate) && flat_enough) {
        accepted = true;
        break;
      }
      if (finite && trial_norm <= options.gradient_tolerance) {  // converged inside the search
        accepted = true;
        break;
      }
      if (!finite || trial_slope > 0 || !(armijo || approximate)) {
        high = step;  // too far: the function rose, or the slope turned
      } else {
        low = step;  // still descending steeply: go further
      }
      step = std::isfinite(high) ? 0.5 * (low + high) : 2 * step;
    }
    if (!accepted) return finish(LbfgsStatus::stalled, "the line search found no acceptable step");
    const Eigen::VectorXd s = trial.x - current.x, y = trial.gradient - current.gradient;
    if (s.dot(y) > 1e-12 * s.norm() * y.norm()) {  // keep the pair only with positive curvature
      pairs.emplace_back(s, y);
      if (static_cast<int>(pairs.size()) > std::max(options.memory, 1)) pairs.pop_front();
    }
    current = std::move(trial);
    norm = trial_norm;
    ++result.iterations;
  }
}

}  // namespace altfem
