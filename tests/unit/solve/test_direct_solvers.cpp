#include "shared/common/error.hpp"
#include "shared/solve/cholmod_solver.hpp"
#include "shared/solve/linear_solver.hpp"
#include "tests/unit/solve/test_matrices.hpp"

#include <gtest/gtest.h>

namespace altfem {
namespace {

double relative_error(const Eigen::VectorXd& value, const Eigen::VectorXd& exact) {
  return (value - exact).norm() / exact.norm();
}

std::unique_ptr<LinearSolver> direct_solver(LinearSolverKind kind) {
  LinearSolverOptions options;
  options.kind = kind;
  return make_linear_solver(options);
}

TEST(DirectSolvers, SolveSpdSystemToRoundoff) {
  const Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(12);
  const Eigen::VectorXd exact = Eigen::VectorXd::LinSpaced(matrix.rows(), -1.0, 2.0);
  const Eigen::VectorXd rhs = matrix * exact;
  for (LinearSolverKind kind : {LinearSolverKind::cholmod, LinearSolverKind::ldlt, LinearSolverKind::lu}) {
    auto solver = direct_solver(kind);
    solver->factorize(matrix);
    Eigen::VectorXd solution;
    solver->solve(rhs, solution);
    EXPECT_LT(relative_error(solution, exact), 1e-12) << solver->name();
    EXPECT_EQ(solver->statistics().solves, 1);
    EXPECT_EQ(solver->statistics().iterations, 0);
  }
}

// CHOLMOD's SuiteSparse_long interface, which the solver switches to when a factor
// outgrows int indices (2^31 entries, far beyond a unit test), gives the int one's
// factor and solution: same entries, same flops, same solution to round-off, for a
// compressed matrix and for one that is not, refactorised with new values.
TEST(DirectSolvers, CholmodWithLongIndicesSolvesAsWithIntIndices) {
  Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(10);
  const Eigen::VectorXd exact = Eigen::VectorXd::LinSpaced(matrix.rows(), -1.0, 2.0);
  for (const CholmodFactorisation factorisation :
       {CholmodFactorisation::supernodal_llt, CholmodFactorisation::simplicial_ldlt}) {
    auto narrow = make_cholmod_solver(factorisation);
    auto wide = make_cholmod_solver(factorisation, CholmodIndices::wide);
    for (const double scale : {1.0, 2.5}) {
      Eigen::SparseMatrix<double> scaled = scale * matrix;
      if (scale != 1.0) scaled.uncompress();
      const Eigen::VectorXd rhs = scaled * exact;
      Eigen::VectorXd narrow_solution, wide_solution;
      narrow->factorize(scaled);
      narrow->solve(rhs, narrow_solution);
      wide->factorize(scaled);
      wide->solve(rhs, wide_solution);
      EXPECT_LT(relative_error(wide_solution, exact), 1e-12) << wide->name() << " × " << scale;
      EXPECT_LT(relative_error(wide_solution, narrow_solution), 1e-13) << wide->name() << " × " << scale;
    }
    EXPECT_EQ(wide->statistics().factor_entries, narrow->statistics().factor_entries);
    EXPECT_EQ(wide->statistics().factorisation_flops, narrow->statistics().factorisation_flops);
  }
}

TEST(DirectSolvers, AnalyseOnceFactoriseManyTimes) {
  const Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(8);
  const Eigen::VectorXd rhs = Eigen::VectorXd::Ones(matrix.rows());
  auto solver = direct_solver(LinearSolverKind::cholmod);
  solver->analyze(matrix);
  constexpr int times = 4;
  for (int time = 1; time <= times; ++time) {
    // Same pattern, new values: the symbolic analysis is reused.
    const Eigen::SparseMatrix<double> scaled = static_cast<double>(time) * matrix;
    solver->factorize(scaled);
    Eigen::VectorXd solution;
    solver->solve(rhs, solution);
    EXPECT_LT((scaled * solution - rhs).norm(), 1e-12 * rhs.norm());
  }
  EXPECT_EQ(solver->statistics().analyses, 1);
  EXPECT_EQ(solver->statistics().factorisations, times);
  EXPECT_GE(solver->statistics().analysis_seconds, 0.0);
  EXPECT_GT(solver->statistics().factorisation_seconds, 0.0);
}

TEST(DirectSolvers, ChangedPatternIsAnalysedAgain) {
  for (LinearSolverKind kind :
       {LinearSolverKind::cholmod, LinearSolverKind::ldlt, LinearSolverKind::lu, LinearSolverKind::pcg}) {
    Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(5);
    auto solver = direct_solver(kind);
    solver->factorize(matrix);  // no analyze() yet: factorize analyses first
    EXPECT_EQ(solver->statistics().analyses, 1) << solver->name();
    // A new symmetric pair of entries changes the pattern.
    const auto last = static_cast<int>(matrix.rows() - 1);
    matrix.coeffRef(0, last) = 0.01;
    matrix.coeffRef(last, 0) = 0.01;
    solver->factorize(matrix);
    EXPECT_EQ(solver->statistics().analyses, 2) << solver->name();
    EXPECT_EQ(solver->statistics().factorisations, 2) << solver->name();
    const Eigen::VectorXd rhs = Eigen::VectorXd::Ones(matrix.rows());
    Eigen::VectorXd solution;
    solver->solve(rhs, solution);
    EXPECT_LT((matrix * solution - rhs).norm(), 1e-9 * rhs.norm()) << solver->name();
  }
}

TEST(DirectSolvers, CholmodNamesTheUnknownWhereTheMatrixIsNotDefinite) {
  // Definite but for unknown 7 (basis function 2, y), wherever the ordering puts it.
  Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(6);
  matrix.coeffRef(7, 7) = -matrix.coeff(7, 7);
  auto solver = direct_solver(LinearSolverKind::cholmod);
  try {
    solver->factorize(matrix);
    FAIL() << "CHOLMOD factorised an indefinite matrix";
  } catch (const NumericalError& error) {
    EXPECT_NE(std::string(error.what()).find(": unknown 7, basis function 2 component y)"), std::string::npos)
        << error.what();
  }
}

TEST(DirectSolvers, CholmodRejectsIndefiniteMatrix) {
  const Eigen::SparseMatrix<double> matrix = testing::shifted(testing::elasticity_like_laplacian(6), 2.7);
  auto solver = direct_solver(LinearSolverKind::cholmod);
  try {
    solver->factorize(matrix);
    FAIL() << "CHOLMOD factorised an indefinite matrix";
  } catch (const NumericalError& error) {
    EXPECT_NE(std::string(error.what()).find("matrix is not positive definite (CHOLMOD status 1, column "),
              std::string::npos)
        << error.what();
  }
  Eigen::VectorXd solution;
  EXPECT_THROW(solver->solve(Eigen::VectorXd::Ones(matrix.rows()), solution), std::logic_error);
  // Newton retries with an SPD-projected Hessian of the same pattern: the failed
  // factor must be reusable, without a new analysis.
  const Eigen::SparseMatrix<double> spd = testing::shifted(testing::elasticity_like_laplacian(6), -1.0);
  solver->factorize(spd);
  const Eigen::VectorXd rhs = Eigen::VectorXd::Ones(matrix.rows());
  solver->solve(rhs, solution);
  EXPECT_LT((spd * solution - rhs).norm(), 1e-12 * rhs.norm());
  EXPECT_EQ(solver->statistics().analyses, 1);
  EXPECT_EQ(solver->statistics().factorisations, 1);
}

TEST(DirectSolvers, LdltAndLuSolveSaddlePointSystem) {
  const Eigen::SparseMatrix<double> matrix = testing::saddle_point(6, 20, 0.1);
  const Eigen::VectorXd exact = Eigen::VectorXd::LinSpaced(matrix.rows(), 1.0, -1.0);
  const Eigen::VectorXd rhs = matrix * exact;
  EXPECT_THROW(direct_solver(LinearSolverKind::cholmod)->factorize(matrix), NumericalError);
  for (LinearSolverKind kind : {LinearSolverKind::ldlt, LinearSolverKind::lu}) {
    auto solver = direct_solver(kind);
    solver->factorize(matrix);
    Eigen::VectorXd solution;
    solver->solve(rhs, solution);
    EXPECT_LT(relative_error(solution, exact), 1e-10) << solver->name();
  }
}

TEST(DirectSolvers, LuSolvesShiftedIndefiniteSystem) {
  const Eigen::SparseMatrix<double> matrix = testing::shifted(testing::elasticity_like_laplacian(6), 2.7);
  const Eigen::VectorXd exact = Eigen::VectorXd::LinSpaced(matrix.rows(), 1.0, -1.0);
  auto solver = direct_solver(LinearSolverKind::lu);
  solver->factorize(matrix);
  Eigen::VectorXd solution;
  solver->solve(matrix * exact, solution);
  EXPECT_LT(relative_error(solution, exact), 1e-10);
}

TEST(DirectSolvers, LuRejectsSingularMatrix) {
  Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(3);
  matrix.prune([](Eigen::Index row, Eigen::Index column, double) { return row != 4 && column != 4; });
  EXPECT_THROW(direct_solver(LinearSolverKind::lu)->factorize(matrix), NumericalError);
}

TEST(LinearSolverKinds, NamesRoundTrip) {
  for (std::string_view name : linear_solver_kind_names) {
    const auto kind = linear_solver_kind_from_name(name);
    ASSERT_TRUE(kind.has_value()) << name;
    EXPECT_EQ(linear_solver_kind_name(*kind), name);
    EXPECT_EQ(direct_solver(*kind)->name(), name);
  }
  EXPECT_FALSE(linear_solver_kind_from_name("cholesky").has_value());
}

}  // namespace
}  // namespace altfem
