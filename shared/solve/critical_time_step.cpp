#include "shared/solve/critical_time_step.hpp"

#include <cmath>
#include <limits>

namespace altfem {

double estimate_critical_time_step(const Discretization& discretization, int iterations) {
  const int dofs = discretization.dof_count();
  Eigen::SparseMatrix<double> stiffness = discretization.hessian_pattern();
  discretization.hessian(Eigen::VectorXd::Zero(dofs), stiffness, false);
  Eigen::VectorXd free = Eigen::VectorXd::Ones(dofs);
  for (int dof : discretization.constrained_dofs()) free[dof] = 0;
  // A deterministic start with every mode in it (a constant vector would miss those
  // orthogonal to it).
  Eigen::VectorXd v(dofs);
  for (int i = 0; i < dofs; ++i) v[i] = free[i] * (1.0 + 0.5 * std::sin(1.0 + 7.0 * i));
  const ExplicitMass& mass = discretization.explicit_mass();
  double largest = 0;
  for (int k = 0; k < iterations; ++k) {
    const Eigen::VectorXd w = mass.solve(stiffness * v).cwiseProduct(free);
    // The Rayleigh quotient of the M-symmetric operator: (v, M⁻¹Kv)_M / (v, v)_M.
    largest = v.dot(stiffness * v) / v.dot(mass.multiply(v));
    const double norm = w.norm();
    if (!(norm > 0)) break;
    v = w / norm;
  }
  return largest > 0 ? 2.0 / std::sqrt(largest) : std::numeric_limits<double>::infinity();
}

}  // namespace altfem
