#include "shared/solve/conjugate_gradient.hpp"

#include <string>

namespace altfem {

KrylovResult conjugate_gradient(const Eigen::SparseMatrix<double>& matrix, const Preconditioner& preconditioner,
                                const Eigen::VectorXd& rhs, Eigen::VectorXd& solution, const KrylovSettings& settings,
                                ConjugateGradientWorkspace& workspace) {
  constexpr std::string_view method = "pcg";
  auto& [r, z, p, q] = workspace;
  if (rhs.squaredNorm() == 0) {
    solution.setZero();
    return {};
  }
  const double target = settings.tolerance * rhs.norm();
  int iterations = 0;
  while (true) {  // one pass per (re)start from the current iterate
    const double relative_residual = true_residual(matrix, rhs, solution, r);
    if (has_converged(method, iterations, relative_residual, settings)) return {iterations, relative_residual};
    preconditioner.apply(r, z);
    p = z;
    double r_dot_z = r.dot(z);
    while (iterations < settings.max_iterations) {
      if (!(r_dot_z > 0))
        throw_breakdown(method, iterations,
                        "preconditioner is not positive definite (rᵀM⁻¹r = " + std::to_string(r_dot_z) + ")");
      symmetric_multiply(matrix, p, q);
      const double curvature = p.dot(q);
      if (!(curvature > 0))
        throw_breakdown(method, iterations,
                        "matrix is not positive definite (pᵀAp = " + std::to_string(curvature) + ")");
      const double alpha = r_dot_z / curvature;
      solution += alpha * p;
      r -= alpha * q;
      ++iterations;
      if (r.norm() <= target) break;
      preconditioner.apply(r, z);
      const double previous_r_dot_z = r_dot_z;
      r_dot_z = r.dot(z);
      p = z + (r_dot_z / previous_r_dot_z) * p;
    }
  }
}

}  // namespace altfem
