#include "shared/solve/minres.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace altfem {

KrylovResult minres(const Eigen::SparseMatrix<double>& matrix, const Preconditioner& preconditioner,
                    const Eigen::VectorXd& rhs, Eigen::VectorXd& solution, const KrylovSettings& settings,
                    MinresWorkspace& workspace) {
  constexpr std::string_view method = "minres";
  // Names follow Choi, Paige & Saunders: r1, r2 are the last two (unnormalised)
  // Lanczos vectors, y = M⁻¹ r2, v the normalised Lanczos vector, w the search directions.
  auto& [residual, r1, r2, y, v, w, w2, w1] = workspace;
  if (rhs.squaredNorm() == 0) {
    solution.setZero();
    return {};
  }
  const auto norm_of_preconditioned = [&](const Eigen::VectorXd& vector, const Eigen::VectorXd& preconditioned,
                                          int iterations) {
    const double squared = vector.dot(preconditioned);
    if (squared < 0)
      throw_breakdown(method, iterations,
                      "preconditioner is not positive definite (rᵀM⁻¹r = " + std::to_string(squared) + ")");
    return std::sqrt(squared);
  };
  int iterations = 0;
  while (true) {  // one pass per (re)start from the current iterate
    double relative_residual = true_residual(matrix, rhs, solution, residual);
    if (has_converged(method, iterations, relative_residual, settings)) return {iterations, relative_residual};
    r1 = residual;
    r2 = residual;
    preconditioner.apply(r1, y);
    const double beta1 = norm_of_preconditioned(r1, y, iterations);
    // The recurrence estimates ‖r‖ in the M⁻¹ norm; scale the 2-norm target by
    // the two norms' ratio at the start of this pass.
    const double target = settings.tolerance * rhs.norm() * beta1 / residual.norm();
    double previous_beta = 0, beta = beta1, dbar = 0, epsilon = 0, phibar = beta1, cs = -1, sn = 0;
    w.setZero(rhs.size());
    w2.setZero(rhs.size());
    w1.resize(rhs.size());
    for (int pass_iterations = 0; iterations < settings.max_iterations && beta > 0; ++pass_iterations) {
      v = y / beta;
      symmetric_multiply(matrix, v, y);
      if (pass_iterations > 0) y -= (beta / previous_beta) * r1;
      const double alpha = v.dot(y);
      y -= (alpha / beta) * r2;
      r1.swap(r2);  // r1 ← r2, r2 ← y, y ← M⁻¹ r2 (swaps, no copies)
      r2.swap(y);
      preconditioner.apply(r2, y);
      previous_beta = beta;
      beta = norm_of_preconditioned(r2, y, iterations);
      // Apply the previous Givens rotation, then make the new one (QR of the Lanczos tridiagonal).
      const double previous_epsilon = epsilon;
      const double delta = cs * dbar + sn * alpha;
      const double gbar = sn * dbar - cs * alpha;
      epsilon = sn * beta;
      dbar = -cs * beta;
      const double gamma = std::max(std::hypot(gbar, beta), std::numeric_limits<double>::epsilon());
      cs = gbar / gamma;
      sn = beta / gamma;
      const double phi = cs * phibar;
      phibar *= sn;
      w1.swap(w2);  // w1 ← w2, w2 ← w, w ← new direction
      w2.swap(w);
      w = (v - previous_epsilon * w1 - delta * w2) / gamma;
      solution += phi * w;
      ++iterations;
      if (phibar <= target) break;
    }
  }
}

}  // namespace altfem
