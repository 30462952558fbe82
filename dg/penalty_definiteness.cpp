#include "dg/penalty_definiteness.hpp"

#include <random>

#include "dg/dg_discretization.hpp"
#include "shared/common/error.hpp"
#include "shared/solve/krylov.hpp"
#include "shared/solve/linear_solver.hpp"

namespace altfem::dg {

bool positive_definite(const DgLinearSystem& system, const std::vector<std::vector<int>>& element_dofs,
                       bool iterative) {
  const Eigen::SparseMatrix<double>& stiffness = system.stiffness();
  const Eigen::SparseMatrix<double> mass = system.mass();
  const double shift = 1e-10 * stiffness.diagonal().maxCoeff() / mass.diagonal().maxCoeff();
  // K's pattern holds M's cell blocks: δM is added in place into one copy of K (the sum
  // expression evaluated through temporaries held 2.4 copies, the run's peak).
  Eigen::SparseMatrix<double> shifted = stiffness;
  for (Eigen::Index column = 0; column < mass.outerSize(); ++column)
    for (Eigen::SparseMatrix<double>::InnerIterator entry(mass, column); entry; ++entry)
      shifted.coeffRef(entry.row(), column) += shift * entry.value();
  if (iterative) {
    LinearSolverOptions options;
    options.kind = LinearSolverKind::pcg;
    options.custom_preconditioner = block_jacobi_factory(element_dofs);
    options.tolerance = 1e-8;
    options.max_iterations = 20000;
    const auto solver = make_linear_solver(options);
    std::mt19937 random(35);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    Eigen::VectorXd rhs(shifted.rows()), solution = Eigen::VectorXd::Zero(shifted.rows());
    for (Eigen::Index i = 0; i < rhs.size(); ++i) rhs[i] = uniform(random);
    try {
      solver->factorize(shifted);  // each cell block by Cholesky
      solver->solve(rhs, solution);
      return true;
    } catch (const KrylovBreakdown&) {
      return false;
    } catch (const NumericalError&) {
      if (solver->statistics().factorisations == 0) return false;  // a cell block is not definite
    }
  }
  const auto solver = make_linear_solver({});
  try {
    solver->factorize(shifted);
    return true;
  } catch (const NumericalError&) {
    return false;
  }
}

}  // namespace altfem::dg
