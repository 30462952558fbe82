// Quadrature simplification (shared/quadrature/simplify_quadrature.hpp) on random
// positive rules: at most M points, a subset of the original, positive weights, the
// same monomial integrals; and Lawson–Hanson NNLS on small systems with known answers.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

#include "shared/quadrature/nonnegative_least_squares.hpp"
#include "shared/quadrature/simplify_quadrature.hpp"

namespace altfem {
namespace {

/// Random rule: `count` points in a small box far from the origin (the case the
/// bounding-box scaling of §4.4.3 is for), positive weights.
QuadratureRule random_rule(int count, unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  QuadratureRule rule;
  rule.points.resize(count, 3);
  rule.weights.resize(count);
  for (int i = 0; i < count; ++i) {
    rule.points.row(i) =
        Eigen::RowVector3d(0.7 + 0.02 * unit(generator), -0.3 + 0.05 * unit(generator), 0.1 + 0.01 * unit(generator));
    rule.weights(i) = 1e-6 * (0.1 + unit(generator));
  }
  rule.strength = 4;
  return rule;
}

/// Largest relative difference of ∫ (x − c)^a (y − c)^b (z − c)^c between two rules, over
/// total degree <= degree, c the first rule's first point (so the integrands are not
/// nearly constant), relative to ∫|f| by the first rule.
double largest_moment_difference(const QuadratureRule& a, const QuadratureRule& b, int degree) {
  const Eigen::RowVector3d centre = a.points.row(0);
  double worst = 0.0;
  for (int i = 0; i <= degree; ++i)
    for (int j = 0; i + j <= degree; ++j)
      for (int k = 0; i + j + k <= degree; ++k) {
        const auto integrate = [&](const QuadratureRule& rule, bool absolute) {
          double sum = 0.0;
          for (Eigen::Index q = 0; q < rule.points.rows(); ++q) {
            const Eigen::RowVector3d y = rule.points.row(q) - centre;
            const double f = std::pow(y(0), i) * std::pow(y(1), j) * std::pow(y(2), k);
            sum += rule.weights(q) * (absolute ? std::abs(f) : f);
          }
          return sum;
        };
        worst = std::max(worst, std::abs(integrate(a, false) - integrate(b, false)) / integrate(a, true));
      }
  return worst;
}

class SimplifyQuadrature : public ::testing::TestWithParam<SimplificationMethod> {};

TEST_P(SimplifyQuadrature, KeepsMomentsWithAtMostMPositiveWeightsOnASubset) {
  for (int degree = 1; degree <= 6; ++degree) {
    const QuadratureRule rule = random_rule(1500, 100 + degree);
    const SimplificationResult result = simplify_quadrature(rule, {degree, GetParam(), 1e-12});
    ASSERT_TRUE(result.simplified) << "degree " << degree;
    EXPECT_FALSE(result.failed);
    EXPECT_LE(result.residual, 1e-12);
    const Eigen::Index basis_size = (degree + 1) * (degree + 2) * (degree + 3) / 6;
    EXPECT_LE(result.rule.points.rows(), basis_size);
    EXPECT_GT(result.rule.weights.minCoeff(), 0.0);
    std::set<std::tuple<double, double, double>> original;
    for (Eigen::Index i = 0; i < rule.points.rows(); ++i)
      original.emplace(rule.points(i, 0), rule.points(i, 1), rule.points(i, 2));
    for (Eigen::Index i = 0; i < result.rule.points.rows(); ++i)
      EXPECT_TRUE(original.count({result.rule.points(i, 0), result.rule.points(i, 1), result.rule.points(i, 2)}));
    EXPECT_LE(largest_moment_difference(rule, result.rule, degree), 1e-12) << "degree " << degree;
  }
}

TEST_P(SimplifyQuadrature, SmallRulesAreReturnedUnchanged) {
  const QuadratureRule rule = random_rule(20, 7);
  const SimplificationResult result = simplify_quadrature(rule, {3, GetParam(), 1e-12});
  EXPECT_FALSE(result.simplified);
  EXPECT_FALSE(result.failed);
  EXPECT_EQ(result.rule.points, rule.points);
  EXPECT_EQ(result.rule.weights, rule.weights);
}

TEST_P(SimplifyQuadrature, RejectsNegativeWeights) {
  QuadratureRule rule = random_rule(50, 8);
  rule.weights(3) = -1.0;
  EXPECT_THROW(simplify_quadrature(rule, {2, GetParam(), 1e-12}), std::invalid_argument);
}

TEST_P(SimplifyQuadrature, AnImpossibleToleranceKeepsTheOriginalAndSaysSo) {
  const QuadratureRule rule = random_rule(300, 9);
  const SimplificationResult result = simplify_quadrature(rule, {3, GetParam(), 0.0});
  ASSERT_GT(result.residual, 0.0);  // rounding alone makes it positive
  EXPECT_TRUE(result.failed);
  EXPECT_FALSE(result.simplified);
  EXPECT_EQ(result.rule.points.rows(), rule.points.rows());
}

INSTANTIATE_TEST_SUITE_P(Methods, SimplifyQuadrature,
                         ::testing::Values(SimplificationMethod::linear_program,
                                           SimplificationMethod::nonnegative_least_squares,
                                           SimplificationMethod::caratheodory),
                         [](const auto& info) { return std::string(simplification_method_name(info.param)); });

TEST(NonnegativeLeastSquares, ActiveConstraintAndExactSolution) {
  // min ‖A x − b‖ with x >= 0: the unconstrained solution (1, −1) is infeasible; the
  // answer puts x₂ = 0 and x₁ = b·a₁/‖a₁‖² = 0.5.
  Eigen::MatrixXd A(2, 2);
  A << 1, 0, 1, 2;
  Eigen::VectorXd b = A * Eigen::Vector2d(1.0, -1.0);  // (1, −1)
  const auto result = nonnegative_least_squares(A, b);
  EXPECT_TRUE(result.converged);
  EXPECT_NEAR(result.solution(0), 0.0, 1e-15);  // a₁·b = 0: nothing helps; x = 0
  EXPECT_NEAR(result.solution(1), 0.0, 1e-15);
  b = Eigen::Vector2d(2.0, 4.0);  // = A (2, 1) exactly, feasible
  const auto exact = nonnegative_least_squares(A, b);
  EXPECT_NEAR(exact.solution(0), 2.0, 1e-14);
  EXPECT_NEAR(exact.solution(1), 1.0, 1e-14);
  EXPECT_LT(exact.residual_norm, 1e-14);
}

}  // namespace
}  // namespace altfem
