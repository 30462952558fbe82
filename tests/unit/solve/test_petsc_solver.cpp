// solver.linear "petsc": PETSc's Krylov solvers behind altfem's LinearSolver interface
// give the direct solvers' solution to their tolerance, read the matrix through the
// transposed (compressed-row) pattern correctly, refresh values in place, and turn
// PETSc's failures into altfem's errors.
#include "shared/common/error.hpp"
#include "shared/solve/linear_solver.hpp"
#include "shared/solve/petsc_solver.hpp"
#include "tests/unit/solve/test_matrices.hpp"

#include <gtest/gtest.h>

namespace altfem {
namespace {

LinearSolverOptions petsc(const std::string& petsc_options, double tolerance = 1e-10) {
  LinearSolverOptions options;
  options.kind = LinearSolverKind::petsc;
  options.petsc_options = petsc_options;
  options.tolerance = tolerance;
  return options;
}

Eigen::VectorXd direct_solution(const Eigen::SparseMatrix<double>& matrix, const Eigen::VectorXd& rhs) {
  LinearSolverOptions options;
  options.kind = LinearSolverKind::lu;
  const auto solver = make_linear_solver(options);
  solver->factorize(matrix);
  Eigen::VectorXd solution;
  solver->solve(rhs, solution);
  return solution;
}

class PetscSolver : public ::testing::Test {
protected:
  void SetUp() override {
    if (!petsc_available()) GTEST_SKIP() << "built without PETSc (-DALTFEM_PETSC=OFF)";
  }
};

// CG stops at ‖b − A x‖ ≤ 1e-10 ‖b‖ (the unpreconditioned residual, as altfem's own
// solvers): the error is then below κ · 1e-10 relative, κ < 100 for this matrix.
TEST_F(PetscSolver, CgWithGamgSolvesAnSpdSystemToItsTolerance) {
  const Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(8);
  const Eigen::VectorXd rhs = Eigen::VectorXd::LinSpaced(matrix.rows(), -1.0, 2.0);
  const auto solver = make_linear_solver(petsc("-ksp_type cg -pc_type gamg"));
  solver->factorize(matrix);
  Eigen::VectorXd solution;
  solver->solve(rhs, solution);
  EXPECT_LE((rhs - matrix * solution).norm(), 1e-10 * rhs.norm());
  EXPECT_LT((solution - direct_solution(matrix, rhs)).norm(), 1e-8 * solution.norm());
  EXPECT_EQ(solver->name(), "petsc");
  EXPECT_EQ(solver->statistics().analyses, 1);
  EXPECT_EQ(solver->statistics().factorisations, 1);
  EXPECT_EQ(solver->statistics().solves, 1);
  EXPECT_GT(solver->statistics().iterations, 0);
}

// A nonsymmetric matrix tells A from Aᵀ: Eigen stores columns, PETSc rows, so a pattern
// read without transposing would solve Aᵀ x = b.
TEST_F(PetscSolver, GmresSolvesANonsymmetricSystemNotItsTranspose) {
  Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(5);
  for (int row = 1; row < matrix.rows(); ++row) matrix.coeffRef(row, row - 1) += 0.4;
  matrix.makeCompressed();
  const Eigen::VectorXd rhs = Eigen::VectorXd::LinSpaced(matrix.rows(), 1.0, -3.0);
  // Right preconditioning: GMRES then measures the unpreconditioned residual.
  const auto solver = make_linear_solver(petsc("-ksp_type gmres -ksp_pc_side right -pc_type jacobi"));
  solver->factorize(matrix);
  Eigen::VectorXd solution;
  solver->solve(rhs, solution);
  EXPECT_LE((rhs - matrix * solution).norm(), 1e-10 * rhs.norm());
  EXPECT_LT((solution - direct_solution(matrix, rhs)).norm(), 1e-8 * solution.norm());
}

// New values on the same pattern reach PETSc without a new analysis: 3A x = b gives x/3.
TEST_F(PetscSolver, NewValuesOnTheSamePatternAreRefreshedInPlace) {
  const Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(6);
  const Eigen::VectorXd rhs = Eigen::VectorXd::Ones(matrix.rows());
  const auto solver = make_linear_solver(petsc("-ksp_type cg -pc_type jacobi", 1e-12));
  Eigen::VectorXd first, second;
  solver->factorize(matrix);
  solver->solve(rhs, first);
  const Eigen::SparseMatrix<double> tripled = 3.0 * matrix;
  solver->factorize(tripled);
  solver->solve(rhs, second);
  EXPECT_LT((3.0 * second - first).norm(), 1e-10 * first.norm());
  EXPECT_EQ(solver->statistics().analyses, 1);
  EXPECT_EQ(solver->statistics().factorisations, 2);
}

// The near-null space must be one vector per column of the matrix's size; PETSc
// receives it orthonormalised, so any basis of the rigid modes will do.
TEST_F(PetscSolver, ANearNullSpaceOfTheWrongSizeIsAProgrammingError) {
  const Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(4);
  LinearSolverOptions options = petsc("-ksp_type cg -pc_type gamg");
  options.near_null_space = Eigen::MatrixXd::Random(matrix.rows() + 3, 6);
  EXPECT_THROW(make_linear_solver(options)->factorize(matrix), std::logic_error);
  options.near_null_space = Eigen::MatrixXd::Random(matrix.rows(), 6);
  const auto solver = make_linear_solver(options);
  solver->factorize(matrix);
  Eigen::VectorXd solution;
  const Eigen::VectorXd rhs = Eigen::VectorXd::Ones(matrix.rows());
  solver->solve(rhs, solution);
  EXPECT_LE((rhs - matrix * solution).norm(), 1e-10 * rhs.norm());
}

TEST_F(PetscSolver, AnUnknownTypeIsBadInputNamingTheKey) {
  try {
    make_linear_solver(petsc("-ksp_type cg -pc_type no_such_preconditioner"));
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("solver.petsc_options"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("no_such_preconditioner"), std::string::npos) << error.what();
  }
}

TEST_F(PetscSolver, TooFewIterationsAreANumericalErrorWithPetscsReason) {
  const Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(6);
  const auto solver = make_linear_solver(petsc("-ksp_type cg -pc_type none -ksp_max_it 2"));
  solver->factorize(matrix);
  Eigen::VectorXd solution;
  try {
    solver->solve(Eigen::VectorXd::Ones(matrix.rows()), solution);
    FAIL() << "expected NumericalError";
  } catch (const NumericalError& error) {
    EXPECT_NE(std::string(error.what()).find("DIVERGED_ITS after 2 iterations"), std::string::npos) << error.what();
  }
}

// Two solvers in one process (a run and its rebuild after an event) keep their own options.
TEST_F(PetscSolver, TwoSolversKeepTheirOwnOptions) {
  const Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(6);
  const auto limited = make_linear_solver(petsc("-ksp_type cg -pc_type none -ksp_max_it 2"));
  const auto free = make_linear_solver(petsc("-ksp_type cg -pc_type none"));
  limited->factorize(matrix);
  free->factorize(matrix);
  Eigen::VectorXd solution;
  const Eigen::VectorXd rhs = Eigen::VectorXd::Ones(matrix.rows());
  EXPECT_NO_THROW(free->solve(rhs, solution));
  EXPECT_THROW(limited->solve(rhs, solution), NumericalError);
}

}  // namespace
}  // namespace altfem
