#include "shared/common/error.hpp"
#include "shared/solve/lbfgs.hpp"

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include <cmath>
#include <limits>

namespace altfem {
namespace {

// The extended Rosenbrock function Σ 100 (x₂ᵢ − x₂ᵢ₋₁²)² + (1 − x₂ᵢ₋₁)², minimum 0 at x = 1.
double rosenbrock(const Eigen::VectorXd& x, Eigen::VectorXd& gradient) {
  gradient.setZero(x.size());
  double value = 0;
  for (Eigen::Index i = 0; i + 1 < x.size(); i += 2) {
    const double bend = x[i + 1] - x[i] * x[i];
    const double offset = 1 - x[i];
    value += 100 * bend * bend + offset * offset;
    gradient[i] = -400 * bend * x[i] - 2 * offset;
    gradient[i + 1] = 200 * bend;
  }
  return value;
}

TEST(Lbfgs, MinimisesRosenbrock) {
  Eigen::VectorXd x(10);
  for (Eigen::Index i = 0; i < x.size(); i += 2) x.segment<2>(i) << -1.2, 1.0;
  const LbfgsResult result = minimize_lbfgs(rosenbrock, x);
  EXPECT_EQ(result.status, LbfgsStatus::converged) << result.detail;
  EXPECT_LE(result.gradient_norm, 1e-8);
  EXPECT_LT((x - Eigen::VectorXd::Ones(10)).norm(), 1e-7);
  Eigen::VectorXd gradient;
  EXPECT_NEAR(rosenbrock(x, gradient), result.objective, 0.0);
  EXPECT_LE(gradient.norm(), 1e-8);
  EXPECT_GT(result.evaluations, 10);
}

TEST(Lbfgs, MinimisesConvexQuadratic) {
  // f = ½ xᵀ A x − bᵀ x with A = tridiag(−1, 2 + i/10, −1), minimiser A⁻¹ b.
  constexpr int n = 60;
  Eigen::MatrixXd matrix = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    matrix(i, i) = 2 + i / 10.0;
    if (i + 1 < n) matrix(i, i + 1) = matrix(i + 1, i) = -1;
  }
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 1.0);
  const auto quadratic = [&](const Eigen::VectorXd& x, Eigen::VectorXd& gradient) {
    gradient = matrix * x - b;
    return 0.5 * x.dot(matrix * x) - b.dot(x);
  };
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  const LbfgsResult result = minimize_lbfgs(quadratic, x);
  EXPECT_EQ(result.status, LbfgsStatus::converged) << result.detail;
  EXPECT_LE(result.gradient_norm, 1e-8);
  const Eigen::VectorXd exact = matrix.ldlt().solve(b);
  EXPECT_LT((x - exact).norm(), 1e-8 * exact.norm());
}

TEST(Lbfgs, InfiniteValueMakesTheLineSearchBacktrack) {
  // f = Σ 100 xᵢ² − log xᵢ is +inf for any xᵢ ≤ 0 (like an inverted element);
  // minimiser xᵢ = 1/√200. From xᵢ in [0.5, 0.9] the first step (steepest descent,
  // moving the largest coordinate by 1) lands below 0: the line search must shrink it.
  int infinite_values = 0;
  const auto barrier = [&](const Eigen::VectorXd& x, Eigen::VectorXd& gradient) {
    gradient = 200 * x - x.cwiseInverse();
    if ((x.array() <= 0).any()) {
      ++infinite_values;
      return std::numeric_limits<double>::infinity();
    }
    // A scalar loop: Eigen's vectorised log trips GCC 12's -Wuninitialized with AVX-512.
    double value = 0;
    for (double coordinate : x) value += 100 * coordinate * coordinate - std::log(coordinate);
    return value;
  };
  Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(8, 0.5, 0.9);
  const LbfgsResult result = minimize_lbfgs(barrier, x);
  EXPECT_EQ(result.status, LbfgsStatus::converged) << result.detail;
  EXPECT_GT(infinite_values, 0);
  EXPECT_LT((x - Eigen::VectorXd::Constant(8, std::sqrt(1.0 / 200))).norm(), 1e-8);
}

TEST(Lbfgs, StopsAtMaxEvaluationsWithBestPoint) {
  Eigen::VectorXd x(2);
  x << -1.2, 1.0;
  LbfgsOptions options;
  options.max_evaluations = 5;
  const LbfgsResult result = minimize_lbfgs(rosenbrock, x, options);
  EXPECT_EQ(result.status, LbfgsStatus::max_evaluations) << result.detail;
  EXPECT_EQ(result.evaluations, 5);
  Eigen::VectorXd gradient;
  EXPECT_EQ(rosenbrock(x, gradient), result.objective);
  EXPECT_LT(result.objective, 24.2);  // f(−1.2, 1) = 24.2
}

TEST(Lbfgs, ObjectiveExceptionPropagatesUnchanged) {
  const auto failing = [](const Eigen::VectorXd& x, Eigen::VectorXd& gradient) -> double {
    gradient = x;
    throw NumericalError("element 7 inverted");
  };
  Eigen::VectorXd x = Eigen::VectorXd::Ones(3);
  try {
    minimize_lbfgs(failing, x);
    FAIL() << "exception swallowed";
  } catch (const NumericalError& error) {
    EXPECT_STREQ(error.what(), "element 7 inverted");
  }
}

}  // namespace
}  // namespace altfem
