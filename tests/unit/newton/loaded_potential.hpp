#pragma once
// The static potential Ψ(u) − f·u of an assembler under a fixed load, as a Newton
// Objective, and a static solve with strong Dirichlet values (used by the newton
// unit tests and the fem verification tests, which need body forces that the
// Discretization interface does not carry).
#include <algorithm>
#include <vector>

#include "shared/assembly/elastic_assembler.hpp"
#include "shared/solve/newton.hpp"

namespace altfem::test {

class LoadedPotential final : public Objective {
public:
  LoadedPotential(const ElasticAssembler& assembler, Eigen::VectorXd force, const DirichletElimination& elimination)
      : assembler_(assembler), force_(std::move(force)), elimination_(elimination) {}
  double value(const Eigen::VectorXd& u) const override { return assembler_.energy(u) - force_.dot(u); }
  /// Also records the free gradient norm (Newton evaluates the gradient once per iteration).
  void gradient(const Eigen::VectorXd& u, Eigen::VectorXd& gradient) const override {
    assembler_.gradient(u, gradient);
    gradient -= force_;
    residuals.push_back(elimination_.free_norm(gradient));
  }
  void hessian(const Eigen::VectorXd& u, Eigen::SparseMatrix<double>& hessian, bool project_spd) const override {
    assembler_.hessian(u, hessian, project_spd);
  }
  bool hessian_is_constant() const override { return assembler_.is_linear(); }

  mutable std::vector<double> residuals;

private:
  const ElasticAssembler& assembler_;
  Eigen::VectorXd force_;
  const DirichletElimination& elimination_;
};

/// Minimises Ψ(u) − f·u from u = 0 with the DOFs `constrained` held at `prescribed`
/// (same order). Newton stops at a free residual of relative_tolerance × the larger
/// of ‖f‖ and the initial free residual with the constraints in place.
inline Eigen::VectorXd solve_static(const ElasticAssembler& assembler, const Eigen::VectorXd& force,
                                    std::vector<int> constrained, const Eigen::VectorXd& prescribed,
                                    LinearSolverStatistics* statistics = nullptr, double relative_tolerance = 1e-11) {
  if (!std::is_sorted(constrained.begin(), constrained.end()))
    throw std::invalid_argument("solve_static: constrained DOFs must be ascending");
  const DirichletElimination elimination(assembler.pattern(), std::move(constrained));
  const LoadedPotential potential(assembler, force, elimination);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(assembler.dof_count()), gradient;
  elimination.set_constrained(u, prescribed);
  potential.gradient(u, gradient);
  u.setZero();
  NewtonOptions options;
  options.tolerance = relative_tolerance * std::max(force.norm(), elimination.free_norm(gradient));
  const auto solver = make_linear_solver({});
  NewtonSolver newton(*solver, assembler.pattern(), elimination);
  newton.minimize(potential, u, prescribed, options, 0);
  if (statistics) *statistics = solver->statistics();
  return u;
}

}  // namespace altfem::test
