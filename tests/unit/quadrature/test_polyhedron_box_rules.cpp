// The bounding-box rules of Martin et al. 2008 §6 on polyhedra: subdivision exact on
// cells whose faces lie on the boxes' faces, first order in the box size where a face cuts
// the boxes at an angle; Monte Carlo unbiased with the error O(1/√N) its variance predicts,
// and reproducible from its seed. Moments against shared/geometry/polyhedron_moments.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "shared/geometry/monomial_index.hpp"
#include "shared/geometry/polyhedron_moments.hpp"
#include "shared/quadrature/polyhedron_monte_carlo_rule.hpp"
#include "shared/quadrature/polyhedron_subdivision_rule.hpp"
#include "tests/unit/polyhedra.hpp"

namespace altfem {
namespace {

// A triangular prism whose sides are at angles to the x and y axes: they cut the boxes.
Polyhedron skewed_prism() { return test::prism({{0, 0}, {1, 0.1}, {0.2, 1}}, 0.9, {0.05, -0.1, 0.2}); }

// Σ w_q m(x_q) − ∫ m for the monomials m of degree ≤ `degree` (polyhedron_moments' order).
Eigen::VectorXd moment_errors(const PolyhedronRule& rule, const Polyhedron& polyhedron, int degree) {
  const auto exponents = monomial_exponents(degree);
  Eigen::VectorXd errors = -polyhedron_moments(polyhedron, degree);
  for (Eigen::Index q = 0; q < rule.weights.size(); ++q)
    for (Eigen::Index m = 0; m < exponents.rows(); ++m)
      errors[m] += rule.weights[q] * std::pow(rule.points(q, 0), exponents(m, 0)) *
                   std::pow(rule.points(q, 1), exponents(m, 1)) * std::pow(rule.points(q, 2), exponents(m, 2));
  return errors;
}

TEST(PolyhedronSubdivisionRule, ExactWhenTheFacesLieOnBoxFaces) {
  // The box is its own bounding box at every level; the L-prism's re-entrant faces at
  // x = 1 and y = 1 halve its box [0,2]² × [0,0.7] from level 1 on.
  const Polyhedron box = test::box({0.1, -0.3, 0.2}, {0.9, 0.4, 1.7});
  for (int levels : {0, 1, 3})
    for (int strength : {1, 4}) {
      const PolyhedronRule rule = polyhedron_subdivision_rule(box, strength, levels);
      EXPECT_TRUE(rule.positive);
      EXPECT_LT(moment_errors(rule, box, strength).cwiseAbs().maxCoeff(), 1e-12) << levels << " levels";
    }
  const Polyhedron prism = test::l_prism();
  for (int levels : {1, 2, 3}) {
    const PolyhedronRule rule = polyhedron_subdivision_rule(prism, 3, levels);
    EXPECT_EQ(rule.weights.size(), 3 * (1 << (2 * levels)) / 4 * (1 << levels) * 8);  // ¾ of the boxes, 2³ points each
    EXPECT_LT(moment_errors(rule, prism, 3).cwiseAbs().maxCoeff(), 1e-12) << levels << " levels";
  }
}

TEST(PolyhedronSubdivisionRule, FirstOrderInTheBoxSizeWhereFacesCutTheBoxes) {
  // Boxes the faces cut are kept or dropped whole: a layer of thickness O(h) around the
  // boundary in error, so error ≤ C h. Its signs partly cancel, and by how much varies
  // with how the faces meet the grid, so the error is not monotone in h (measured: largest
  // relative moment error 8.2e-2, 1.7e-2, 3.0e-3, 8.8e-4, 2.2e-3 at levels 2 to 6); checked
  // against C h with C from level 2 and twice its size of slack.
  const Polyhedron cell = skewed_prism();
  const double volume = polyhedron_moments(cell, 0)[0];
  std::printf("  levels  points   volume error   first-moment error\n");
  double first = 0, last = 0;
  for (int levels = 2; levels <= 6; ++levels) {
    const PolyhedronRule rule = polyhedron_subdivision_rule(cell, 1, levels);
    const Eigen::VectorXd errors = moment_errors(rule, cell, 1) / volume;
    const double error = errors.cwiseAbs().maxCoeff();
    std::printf("  %6d %7ld  %13.3e  %13.3e\n", levels, static_cast<long>(rule.weights.size()), std::abs(errors[0]),
                errors.tail(3).cwiseAbs().maxCoeff());
    if (levels == 2) first = error;
    EXPECT_LE(error, 2 * first / (1 << (levels - 2))) << levels << " levels";
    last = error;
  }
  EXPECT_LT(last, first / 12);  // four halvings of h: at least first order overall
  EXPECT_GT(last, 1e-8);        // and not exact: the test would not see a rule that ignored the cut
}

TEST(PolyhedronMonteCarloRule, ErrorFollowsItsStandardDeviation) {
  // The volume estimate is vol(B)·(inside/N), binomial: sd = vol(B)·√(p(1−p)/N), p =
  // vol(P)/vol(B). Over 32 seeds the RMS error must lie within a factor 2 of that sd (a
  // χ² with 32 degrees of freedom leaves it within [0.73, 1.25] at 99.9%), at every N,
  // so the error falls as 1/√N.
  const Polyhedron cell = skewed_prism();
  const double volume = polyhedron_moments(cell, 0)[0];
  const Eigen::Vector3d extent = cell.vertices.colwise().maxCoeff() - cell.vertices.colwise().minCoeff();
  const double box_volume = extent.prod(), p = volume / box_volume;
  std::printf("  points  rms volume error  predicted sd  rms first-moment error\n");
  for (int count : {100, 1000, 10000}) {
    double squared = 0, moment_squared = 0;
    const int seeds = 32;
    for (int seed = 0; seed < seeds; ++seed) {
      const Eigen::VectorXd errors = moment_errors(polyhedron_monte_carlo_rule(cell, count, seed), cell, 1);
      squared += errors[0] * errors[0];
      moment_squared += errors.tail(3).squaredNorm() / 3;
    }
    const double rms = std::sqrt(squared / seeds), predicted = box_volume * std::sqrt(p * (1 - p) / count);
    std::printf("  %6d  %16.3e  %12.3e  %22.3e\n", count, rms, predicted, std::sqrt(moment_squared / seeds));
    EXPECT_GT(rms, predicted / 2) << count << " points";
    EXPECT_LT(rms, predicted * 2) << count << " points";
  }
}

TEST(PolyhedronMonteCarloRule, ReproducibleFromItsSeedAndInsideTheCell) {
  const Polyhedron prism = test::l_prism();
  const PolyhedronRule rule = polyhedron_monte_carlo_rule(prism, 500, 7);
  const PolyhedronRule again = polyhedron_monte_carlo_rule(prism, 500, 7);
  EXPECT_EQ(rule.points, again.points);
  EXPECT_EQ(rule.weights, again.weights);
  EXPECT_NE(rule.points, polyhedron_monte_carlo_rule(prism, 500, 8).points);
  EXPECT_TRUE(rule.positive);
  // ¾ of [0,2]² × [0,0.7] is the prism: about 375 of 500 inside, none in the missing quarter.
  EXPECT_NEAR(rule.weights.size(), 375, 40);
  for (Eigen::Index q = 0; q < rule.weights.size(); ++q) EXPECT_FALSE(rule.points(q, 0) > 1 && rule.points(q, 1) > 1);
  EXPECT_DOUBLE_EQ(rule.weights[0], 2.0 * 2.0 * 0.7 / 500);
}

TEST(PolyhedronBoxRules, RejectBadArguments) {
  const Polyhedron prism = test::l_prism();
  EXPECT_THROW(polyhedron_subdivision_rule(Polyhedron{}, 2, 2), std::invalid_argument);
  EXPECT_THROW(polyhedron_subdivision_rule(prism, 2, -1), std::invalid_argument);
  EXPECT_THROW(polyhedron_subdivision_rule(prism, -1, 2), std::invalid_argument);
  EXPECT_THROW(polyhedron_monte_carlo_rule(Polyhedron{}, 10, 0), std::invalid_argument);
  EXPECT_THROW(polyhedron_monte_carlo_rule(prism, 0, 0), std::invalid_argument);
}

}  // namespace
}  // namespace altfem
