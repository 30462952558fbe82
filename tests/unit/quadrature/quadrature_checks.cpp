#include "quadrature_checks.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

namespace altfem::testing {
namespace {

// ∫_{[-1,1]} x^a dx and ∫_{[-1,1]} |x|^a dx.
double box_integral(int a) { return a % 2 == 0 ? 2.0 / (a + 1) : 0.0; }
double box_absolute_integral(int a) { return 2.0 / (a + 1); }

// ∫ x^a y^b z^c over the unit d-simplex = a! b! c! / (a + b + c + d)!, accumulated as
// a product of ratios so that no factorial overflows.
double simplex_integral(const std::vector<int>& exponents) {
  double value = 1.0;
  int denominator = 0;
  for (int a : exponents)
    for (int k = 1; k <= a; ++k) value *= static_cast<double>(k) / ++denominator;
  for (std::size_t d = 1; d <= exponents.size(); ++d) value /= ++denominator;
  return value;
}

// Calls visit(exponents) for every exponent vector of length `dimension` with sum <= degree.
template <class Visit>
void for_each_monomial(int dimension, int degree, Visit&& visit) {
  std::vector<int> exponents(dimension, 0);
  while (true) {
    visit(exponents);
    int d = 0;
    for (; d < dimension; ++d) {
      ++exponents[d];
      int sum = 0;
      for (int e : exponents) sum += e;
      if (sum <= degree) break;
      exponents[d] = 0;
    }
    if (d == dimension) return;
  }
}

}  // namespace

double largest_monomial_error(const QuadratureRule& rule, Shape shape, int degree, std::string* worst) {
  const auto dimension = static_cast<int>(rule.points.cols());
  const auto count = rule.points.rows();
  // powers[d](i, a) = x_{i,d}^a
  std::vector<Eigen::MatrixXd> powers(dimension, Eigen::MatrixXd::Ones(count, degree + 1));
  for (int d = 0; d < dimension; ++d)
    for (int a = 1; a <= degree; ++a)
      for (Eigen::Index i = 0; i < count; ++i) powers[d](i, a) = powers[d](i, a - 1) * rule.points(i, d);

  double largest = 0.0;
  for_each_monomial(dimension, degree, [&](const std::vector<int>& exponents) {
    double sum = 0.0;
    for (Eigen::Index i = 0; i < count; ++i) {
      double term = rule.weights(i);
      for (int d = 0; d < dimension; ++d) term *= powers[d](i, exponents[d]);
      sum += term;
    }
    double exact = 1.0, absolute = 1.0;
    for (int d = 0; d < dimension && shape == Shape::box; ++d) {
      exact *= box_integral(exponents[d]);
      absolute *= box_absolute_integral(exponents[d]);
    }
    if (shape == Shape::simplex) exact = absolute = simplex_integral(exponents);
    const double error = std::abs(sum - exact) / std::max(std::abs(exact), absolute);
    if (error > largest || std::isnan(error)) {
      largest = std::isnan(error) ? INFINITY : error;
      if (worst) {
        std::ostringstream name;
        name << "exponents";
        for (int e : exponents) name << ' ' << e;
        *worst = name.str();
      }
    }
  });
  return largest;
}

namespace {

// Every weight > 0 and every point at least `margin` inside (a negative margin admits
// points that far outside).
::testing::AssertionResult positive_and_inside(const QuadratureRule& rule, Shape shape, double margin) {
  if (rule.points.rows() != rule.weights.size() || rule.points.rows() == 0)
    return ::testing::AssertionFailure() << rule.points.rows() << " points but " << rule.weights.size() << " weights";
  for (Eigen::Index i = 0; i < rule.points.rows(); ++i) {
    if (!(rule.weights(i) > 0.0)) return ::testing::AssertionFailure() << "weight " << i << " = " << rule.weights(i);
    // The distance to the nearest face, in the max-norm for boxes.
    double depth = 1.0, coordinate_sum = 0.0;
    for (Eigen::Index d = 0; d < rule.points.cols(); ++d) {
      const double x = rule.points(i, d);
      depth = std::min(depth, shape == Shape::box ? 1.0 - std::abs(x) : x);
      coordinate_sum += x;
    }
    if (shape == Shape::simplex) depth = std::min(depth, 1.0 - coordinate_sum);
    if (!(depth > margin))
      return ::testing::AssertionFailure()
             << "point " << i << " = (" << rule.points.row(i) << ") is " << -depth << " outside";
  }
  return ::testing::AssertionSuccess();
}

}  // namespace

::testing::AssertionResult positive_and_interior(const QuadratureRule& rule, Shape shape) {
  return positive_and_inside(rule, shape, 0.0);
}

::testing::AssertionResult positive_and_in_closure(const QuadratureRule& rule, Shape shape) {
  return positive_and_inside(rule, shape, -1e-15);
}

::testing::AssertionResult exact_to_degree(const QuadratureRule& rule, Shape shape, int degree, double tolerance) {
  std::string worst;
  const double error = largest_monomial_error(rule, shape, degree, &worst);
  if (error <= tolerance) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "relative error " << error << " > " << tolerance << " for " << worst
                                       << " (degree <= " << degree << ", " << rule.weights.size() << " points)";
}

}  // namespace altfem::testing
