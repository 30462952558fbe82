#include "shared/solve/conjugate_residual.hpp"

#include <string>

namespace altfem {

KrylovResult conjugate_residual(const Eigen::SparseMatrix<double>& matrix, const Preconditioner& preconditioner,
                                const Eigen::VectorXd& rhs, Eigen::VectorXd& solution, const KrylovSettings& settings,
                                ConjugateResidualWorkspace& workspace) {
  constexpr std::string_view method = "conjugate_residual";
  // r residual, z = M⁻¹r, az = A z, p direction, ap = A p, map = M⁻¹ A p.
  auto& [r, z, az, p, ap, map] = workspace;
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
    symmetric_multiply(matrix, z, az);
    p = z;
    ap = az;
    double z_az = z.dot(az);
    while (iterations < settings.max_iterations) {
      if (z_az == 0) throw_breakdown(method, iterations, "zᵀAz = 0 (indefinite matrix? use minres)");
      preconditioner.apply(ap, map);
      const double ap_map = ap.dot(map);
      if (!(ap_map > 0))
        throw_breakdown(method, iterations,
                        "preconditioner is not positive definite ((Ap)ᵀM⁻¹Ap = " + std::to_string(ap_map) + ")");
      const double alpha = z_az / ap_map;
      solution += alpha * p;
      r -= alpha * ap;
      z -= alpha * map;
      ++iterations;
      if (r.norm() <= target) break;
      symmetric_multiply(matrix, z, az);
      const double previous_z_az = z_az;
      z_az = z.dot(az);
      const double beta = z_az / previous_z_az;
      p = z + beta * p;
      ap = az + beta * ap;
    }
  }
}

}  // namespace altfem
