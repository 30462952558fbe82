#include "shared/common/error.hpp"
#include "shared/solve/incomplete_cholesky_preconditioner.hpp"
#include "shared/solve/jacobi_preconditioner.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace altfem {
namespace {

// n × n tridiagonal, diagonal 2 + i, off-diagonals −1: SPD (diagonally dominant).
Eigen::SparseMatrix<double> tridiagonal(int n) {
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i) {
    entries.emplace_back(i, i, 2.0 + i);
    if (i > 0) entries.emplace_back(i, i - 1, -1.0);
    if (i + 1 < n) entries.emplace_back(i, i + 1, -1.0);
  }
  Eigen::SparseMatrix<double> matrix(n, n);
  matrix.setFromTriplets(entries.begin(), entries.end());
  return matrix;
}

TEST(JacobiPreconditioner, DividesByAbsoluteDiagonal) {
  Eigen::SparseMatrix<double> matrix = tridiagonal(5);
  matrix.coeffRef(2, 2) = -4.0;
  JacobiPreconditioner jacobi;
  jacobi.compute(matrix);
  const Eigen::VectorXd residual = Eigen::VectorXd::Constant(5, 12.0);
  Eigen::VectorXd result;
  jacobi.apply(residual, result);
  const Eigen::VectorXd expected = (Eigen::VectorXd(5) << 6.0, 4.0, 3.0, 2.4, 2.0).finished();
  EXPECT_LT((result - expected).norm(), 1e-15);
}

TEST(JacobiPreconditioner, ZeroDiagonalNamesTheRow) {
  Eigen::SparseMatrix<double> matrix = tridiagonal(6);
  matrix.coeffRef(3, 3) = 0.0;
  JacobiPreconditioner jacobi;
  try {
    jacobi.compute(matrix);
    FAIL() << "zero diagonal accepted";
  } catch (const NumericalError& error) {
    EXPECT_EQ(std::string(error.what()), "Jacobi preconditioner: diagonal entry of row 3 is zero");
  }
}

TEST(IncompleteCholesky, IsExactWithoutFill) {
  // A tridiagonal matrix has no fill in its Cholesky factor, so the incomplete
  // factor is the complete one and M⁻¹ A x = x.
  const Eigen::SparseMatrix<double> matrix = tridiagonal(50);
  IncompleteCholeskyPreconditioner cholesky;
  cholesky.compute(matrix);
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(50, -2.0, 3.0);
  Eigen::VectorXd result;
  cholesky.apply(matrix * x, result);
  EXPECT_LT((result - x).norm(), 1e-12 * x.norm());
}

TEST(Preconditioners, MadeByName) {
  for (std::string_view name : preconditioner_names) EXPECT_NE(make_preconditioner(name), nullptr) << name;
  try {
    make_preconditioner("ilu");
    FAIL() << "unknown name accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              "solver preconditioner: expected one of none, jacobi, incomplete_cholesky, got \"ilu\"");
  }
}

TEST(Preconditioners, IdentityCopies) {
  const auto identity = make_preconditioner("none");
  const Eigen::VectorXd residual = Eigen::VectorXd::LinSpaced(7, 1.0, 7.0);
  Eigen::VectorXd result;
  identity->apply(residual, result);
  EXPECT_EQ(result, residual);
}

}  // namespace
}  // namespace altfem
