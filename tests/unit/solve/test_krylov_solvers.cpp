#include "shared/common/error.hpp"
#include "shared/solve/jacobi_preconditioner.hpp"
#include "shared/solve/linear_solver.hpp"
#include "shared/solve/minres.hpp"
#include "tests/unit/solve/test_matrices.hpp"

#include <gtest/gtest.h>

#include <string>
#include <tuple>

namespace altfem {
namespace {

struct SpdSystem {
  Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(20);  // 24000 unknowns
  Eigen::VectorXd rhs;
  Eigen::VectorXd cholmod_solution;
  SpdSystem() {
    rhs = Eigen::VectorXd::LinSpaced(matrix.rows(), -1.0, 1.0).array().sin() + 0.5;
    auto cholmod = make_linear_solver({});
    cholmod->factorize(matrix);
    cholmod->solve(rhs, cholmod_solution);
  }
};

const SpdSystem& spd_system() {
  static const SpdSystem system;
  return system;
}

LinearSolverOptions iterative(LinearSolverKind kind, std::string preconditioner = "jacobi") {
  LinearSolverOptions options;
  options.kind = kind;
  options.preconditioner = std::move(preconditioner);
  return options;
}

class KrylovOnSpdSystem : public ::testing::TestWithParam<std::tuple<LinearSolverKind, std::string>> {};

TEST_P(KrylovOnSpdSystem, ReachesToleranceAndMatchesCholmod) {
  const auto& [kind, preconditioner] = GetParam();
  const SpdSystem& system = spd_system();
  LinearSolverOptions options = iterative(kind, preconditioner);
  options.tolerance = 1e-12;  // the condition number is ~10³: 1e-12 residual gives < 1e-8 error
  auto solver = make_linear_solver(options);
  solver->factorize(system.matrix);
  Eigen::VectorXd solution;
  solver->solve(system.rhs, solution);
  EXPECT_LE((system.rhs - system.matrix * solution).norm(), options.tolerance * system.rhs.norm());
  EXPECT_LT((solution - system.cholmod_solution).norm(), 1e-8 * system.cholmod_solution.norm());
  EXPECT_GT(solver->statistics().iterations, 10);
  EXPECT_LT(solver->statistics().iterations, 2000);
  EXPECT_EQ(solver->statistics().solves, 1);
}

INSTANTIATE_TEST_SUITE_P(AllMethods, KrylovOnSpdSystem,
                         ::testing::Combine(::testing::Values(LinearSolverKind::pcg, LinearSolverKind::minres,
                                                              LinearSolverKind::conjugate_residual),
                                            ::testing::Values("none", "jacobi", "incomplete_cholesky")),
                         [](const auto& info) {
                           return std::string(linear_solver_kind_name(std::get<0>(info.param))) + "_" +
                                  std::get<1>(info.param);
                         });

TEST(Krylov, IncompleteCholeskyNeedsFewerIterationsThanJacobi) {
  const SpdSystem& system = spd_system();
  long iterations[2] = {};
  int index = 0;
  for (const char* preconditioner : {"jacobi", "incomplete_cholesky"}) {
    auto solver = make_linear_solver(iterative(LinearSolverKind::pcg, preconditioner));
    solver->factorize(system.matrix);
    Eigen::VectorXd solution;
    solver->solve(system.rhs, solution);
    iterations[index++] = solver->statistics().iterations;
  }
  EXPECT_LT(iterations[1], iterations[0]);
}

// Counts its applications; otherwise Jacobi.
class CountingPreconditioner final : public Preconditioner {
public:
  explicit CountingPreconditioner(long& applications) : applications_(applications) {}
  void compute(const Eigen::SparseMatrix<double>& matrix) override { jacobi_.compute(matrix); }
  void apply(const Eigen::VectorXd& residual, Eigen::VectorXd& result) const override {
    ++applications_;
    jacobi_.apply(residual, result);
  }

private:
  long& applications_;
  JacobiPreconditioner jacobi_;
};

TEST(Krylov, CustomPreconditionerFromFactoryIsUsed) {
  const Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(8);
  const Eigen::VectorXd rhs = Eigen::VectorXd::Ones(matrix.rows());
  for (LinearSolverKind kind :
       {LinearSolverKind::pcg, LinearSolverKind::minres, LinearSolverKind::conjugate_residual}) {
    long applications = 0;
    LinearSolverOptions options = iterative(kind, "no such preconditioner: the factory wins");
    options.custom_preconditioner = [&applications] { return std::make_unique<CountingPreconditioner>(applications); };
    auto solver = make_linear_solver(options);
    solver->factorize(matrix);
    Eigen::VectorXd solution;
    solver->solve(rhs, solution);
    EXPECT_LE((rhs - matrix * solution).norm(), 1e-10 * rhs.norm());
    // One application per iteration, plus one per (re)start.
    EXPECT_GE(applications, solver->statistics().iterations) << solver->name();
    EXPECT_LE(applications, solver->statistics().iterations + 3) << solver->name();
  }
}

TEST(Krylov, MinresSolvesIndefiniteSystems) {
  const Eigen::SparseMatrix<double> shifted = testing::shifted(testing::elasticity_like_laplacian(8), 2.7);
  const Eigen::SparseMatrix<double> saddle = testing::saddle_point(8, 20, 0.1);
  for (const auto* matrix : {&shifted, &saddle}) {
    const Eigen::VectorXd exact = Eigen::VectorXd::LinSpaced(matrix->rows(), 1.0, -1.0);
    const Eigen::VectorXd rhs = *matrix * exact;
    LinearSolverOptions options = iterative(LinearSolverKind::minres, "none");
    options.tolerance = 1e-12;
    auto solver = make_linear_solver(options);
    solver->factorize(*matrix);
    Eigen::VectorXd solution;
    solver->solve(rhs, solution);
    EXPECT_LE((rhs - *matrix * solution).norm(), 1e-12 * rhs.norm());
    EXPECT_LT((solution - exact).norm(), 1e-8 * exact.norm());
  }
}

TEST(Krylov, MinresWithJacobiOnShiftedIndefiniteSystem) {
  const Eigen::SparseMatrix<double> matrix = testing::shifted(testing::elasticity_like_laplacian(8), 2.7);
  const Eigen::VectorXd rhs = Eigen::VectorXd::Ones(matrix.rows());
  auto solver = make_linear_solver(iterative(LinearSolverKind::minres, "jacobi"));
  solver->factorize(matrix);
  Eigen::VectorXd solution;
  solver->solve(rhs, solution);
  EXPECT_LE((rhs - matrix * solution).norm(), 1e-10 * rhs.norm());
}

TEST(Krylov, ConjugateGradientDetectsIndefiniteMatrix) {
  const Eigen::SparseMatrix<double> matrix = -testing::elasticity_like_laplacian(4);
  auto solver = make_linear_solver(iterative(LinearSolverKind::pcg, "none"));
  solver->factorize(matrix);
  Eigen::VectorXd solution;
  try {
    solver->solve(Eigen::VectorXd::Ones(matrix.rows()), solution);
    FAIL() << "PCG accepted a negative definite matrix";
  } catch (const NumericalError& error) {
    EXPECT_NE(std::string(error.what()).find("pcg broke down at iteration 0: matrix is not positive definite"),
              std::string::npos)
        << error.what();
  }
}

TEST(Krylov, NonConvergenceNamesIterationsAndResidual) {
  const Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(10);
  for (LinearSolverKind kind :
       {LinearSolverKind::pcg, LinearSolverKind::minres, LinearSolverKind::conjugate_residual}) {
    LinearSolverOptions options = iterative(kind);
    options.max_iterations = 5;
    auto solver = make_linear_solver(options);
    solver->factorize(matrix);
    Eigen::VectorXd solution;
    try {
      solver->solve(Eigen::VectorXd::Ones(matrix.rows()), solution);
      FAIL() << solver->name() << " converged in 5 iterations";
    } catch (const NumericalError& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find(std::string(solver->name()) + " did not converge in 5 iterations (relative residual "),
                std::string::npos)
          << message;
      EXPECT_NE(message.find("> tolerance 1e-10)"), std::string::npos) << message;
    }
  }
}

TEST(Krylov, ZeroRightHandSideGivesZeroSolution) {
  const Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(3);
  for (LinearSolverKind kind :
       {LinearSolverKind::pcg, LinearSolverKind::minres, LinearSolverKind::conjugate_residual}) {
    auto solver = make_linear_solver(iterative(kind));
    solver->factorize(matrix);
    Eigen::VectorXd solution = Eigen::VectorXd::Ones(matrix.rows());
    solver->solve(Eigen::VectorXd::Zero(matrix.rows()), solution);
    EXPECT_EQ(solution.norm(), 0.0);
    EXPECT_EQ(solver->statistics().iterations, 0);
  }
}

TEST(Krylov, FreeFunctionStartsFromInitialGuess) {
  const Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(5);
  const Eigen::VectorXd exact = Eigen::VectorXd::LinSpaced(matrix.rows(), 0.0, 1.0);
  JacobiPreconditioner jacobi;
  jacobi.compute(matrix);
  Eigen::VectorXd solution = exact;  // already the answer: no iteration needed
  MinresWorkspace workspace;
  const KrylovResult result = minres(matrix, jacobi, matrix * exact, solution, {}, workspace);
  EXPECT_EQ(result.iterations, 0);
  EXPECT_LE(result.relative_residual, 1e-14);
}

TEST(Krylov, UnknownPreconditionerIsAnInputError) {
  EXPECT_THROW(make_linear_solver(iterative(LinearSolverKind::pcg, "ilu")), InputError);
}

}  // namespace
}  // namespace altfem
