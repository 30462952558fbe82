#include "shared/quadrature/gauss_legendre.hpp"

#include "quadrature_checks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace altfem {
namespace {

using testing::Shape;

TEST(GaussLegendre, ExactToDegreeTwoNMinusOneForOneToFortyPoints) {
  for (int n = 1; n <= 40; ++n) {
    const QuadratureRule rule = gauss_legendre(n);
    ASSERT_EQ(rule.points.rows(), n);
    EXPECT_EQ(rule.strength, 2 * n - 1);
    EXPECT_TRUE(testing::exact_to_degree(rule, Shape::box, 2 * n - 1)) << n << " points";
    EXPECT_TRUE(testing::positive_and_interior(rule, Shape::box)) << n << " points";
  }
}

TEST(GaussLegendre, NotExactOneDegreeHigher) {
  // x^{2n} is the first monomial an n-point Gauss rule misses: the check above can fail.
  for (int n = 1; n <= 10; ++n)
    EXPECT_GT(testing::largest_monomial_error(gauss_legendre(n), Shape::box, 2 * n), 1e-8) << n << " points";
}

TEST(GaussLegendre, KnownThreePointRule) {
  const QuadratureRule rule = gauss_legendre(3);
  EXPECT_DOUBLE_EQ(rule.points(0, 0), -std::sqrt(0.6));
  EXPECT_NEAR(rule.points(1, 0), 0.0, 1e-16);
  EXPECT_DOUBLE_EQ(rule.points(2, 0), std::sqrt(0.6));
  EXPECT_DOUBLE_EQ(rule.weights(0), 5.0 / 9.0);
  EXPECT_DOUBLE_EQ(rule.weights(1), 8.0 / 9.0);
  EXPECT_DOUBLE_EQ(rule.weights(2), 5.0 / 9.0);
}

TEST(GaussLegendre, RejectsNonPositivePointCount) {
  EXPECT_THROW(gauss_legendre(0), std::invalid_argument);
  EXPECT_THROW(gauss_jacobi(-1, 0.0, 0.0), std::invalid_argument);
  EXPECT_THROW(gauss_jacobi(3, -1.0, 0.0), std::invalid_argument);
}

// ∫_{-1}^{1} x^k (1−x)^alpha (1+x)^beta dx for integer alpha, beta: the integrand is a
// polynomial, integrated exactly by a Gauss–Legendre rule with enough points.
double jacobi_moment(int k, int alpha, int beta) {
  static const QuadratureRule legendre = gauss_legendre(40);
  double sum = 0;
  for (int i = 0; i < 40; ++i) {
    const double x = legendre.points(i, 0);
    sum += legendre.weights(i) * std::pow(x, k) * std::pow(1 - x, alpha) * std::pow(1 + x, beta);
  }
  return sum;
}

TEST(GaussJacobi, ExactForPolynomialTimesIntegerWeight) {
  for (const auto& [alpha, beta] : {std::pair{1, 0}, {2, 0}, {0, 3}, {2, 1}})
    for (int n = 1; n <= 16; ++n) {
      const QuadratureRule rule = gauss_jacobi(n, alpha, beta);
      EXPECT_TRUE(testing::positive_and_interior(rule, Shape::box));
      for (int k = 0; k <= 2 * n - 1; ++k) {
        double sum = 0;
        for (int i = 0; i < n; ++i) sum += rule.weights(i) * std::pow(rule.points(i, 0), k);
        const double exact = jacobi_moment(k, alpha, beta);
        const double scale = jacobi_moment(k % 2 == 0 ? k : k + 1, alpha, beta) + std::abs(exact);
        EXPECT_LE(std::abs(sum - exact), 1e-13 * scale)
            << "alpha " << alpha << " beta " << beta << " n " << n << " k " << k;
      }
    }
}

TEST(GaussJacobi, FractionalExponentsMeanAndMass) {
  // ∫ (1−x)^a (1+x)^b dx = 2^{a+b+1} Γ(a+1) Γ(b+1) / Γ(a+b+2); the mean is (b−a)/(a+b+2).
  const double alpha = -0.5, beta = 1.5;
  const double mass =
      std::exp2(alpha + beta + 1) * std::tgamma(alpha + 1) * std::tgamma(beta + 1) / std::tgamma(alpha + beta + 2);
  const QuadratureRule rule = gauss_jacobi(7, alpha, beta);
  double sum = 0, first_moment = 0;
  for (int i = 0; i < 7; ++i) {
    sum += rule.weights(i);
    first_moment += rule.weights(i) * rule.points(i, 0);
  }
  EXPECT_NEAR(sum, mass, 1e-14 * mass);
  EXPECT_NEAR(first_moment / mass, (beta - alpha) / (alpha + beta + 2), 1e-14);
}

TEST(GaussPointCount, SmallestExactCount) {
  EXPECT_EQ(gauss_point_count(0), 1);
  EXPECT_EQ(gauss_point_count(1), 1);
  EXPECT_EQ(gauss_point_count(2), 2);
  EXPECT_EQ(gauss_point_count(3), 2);
  EXPECT_EQ(gauss_point_count(30), 16);
  EXPECT_THROW(gauss_point_count(-1), std::invalid_argument);
}

}  // namespace
}  // namespace altfem
