#include "shared/solve/iterative_solver.hpp"

#include "shared/solve/conjugate_gradient.hpp"
#include "shared/solve/conjugate_residual.hpp"
#include "shared/solve/minres.hpp"

#include <stdexcept>

namespace altfem {
namespace {

template <class Workspace>
using KrylovMethod = KrylovResult (*)(const Eigen::SparseMatrix<double>&, const Preconditioner&, const Eigen::VectorXd&,
                                      Eigen::VectorXd&, const KrylovSettings&, Workspace&);

template <class Workspace>
class IterativeSolver final : public LinearSolver {
public:
  IterativeSolver(std::string_view name, KrylovMethod<Workspace> method, std::unique_ptr<Preconditioner> preconditioner,
                  const KrylovSettings& settings)
      : name_(name), method_(method), preconditioner_(std::move(preconditioner)), settings_(settings) {}

  std::string_view name() const override { return name_; }

protected:
  void analyze_pattern(const Eigen::SparseMatrix<double>&) override {}
  bool analyses_pattern() const override { return false; }

  // The caller's matrix itself, not a copy (LinearSolver::factorize): a copy was one
  // more stiffness matrix in memory for every run with an iterative solver (issue #35).
  void factorize_values(const Eigen::SparseMatrix<double>& matrix) override {
    matrix_ = &matrix;
    preconditioner_->compute(matrix);
  }

  long solve_system(const Eigen::VectorXd& rhs, Eigen::VectorXd& solution) override {
    solution.setZero(rhs.size());
    return method_(*matrix_, *preconditioner_, rhs, solution, settings_, workspace_).iterations;
  }

private:
  std::string_view name_;
  KrylovMethod<Workspace> method_;
  std::unique_ptr<Preconditioner> preconditioner_;
  KrylovSettings settings_;
  const Eigen::SparseMatrix<double>* matrix_ = nullptr;
  Workspace workspace_;
};

template <class Workspace>
std::unique_ptr<LinearSolver> make(std::string_view name, KrylovMethod<Workspace> method,
                                   std::unique_ptr<Preconditioner> preconditioner, const KrylovSettings& settings) {
  return std::make_unique<IterativeSolver<Workspace>>(name, method, std::move(preconditioner), settings);
}

}  // namespace

std::unique_ptr<LinearSolver> make_iterative_solver(LinearSolverKind kind,
                                                    std::unique_ptr<Preconditioner> preconditioner,
                                                    const KrylovSettings& settings) {
  if (!preconditioner) throw std::logic_error("make_iterative_solver: no preconditioner");
  const std::string_view name = linear_solver_kind_name(kind);
  switch (kind) {
    case LinearSolverKind::pcg: return make(name, &conjugate_gradient, std::move(preconditioner), settings);
    case LinearSolverKind::minres: return make(name, &minres, std::move(preconditioner), settings);
    case LinearSolverKind::conjugate_residual:
      return make(name, &conjugate_residual, std::move(preconditioner), settings);
    default: throw std::logic_error("make_iterative_solver: " + std::string(name) + " is not an iterative solver");
  }
}

}  // namespace altfem
