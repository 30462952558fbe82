// Rules on polyhedra by cone decomposition: every monomial up to the strength against the
// exact moments (shared/geometry/polyhedron_moments), on a convex cell, a star-shaped
// non-convex one (positive weights), one star-shaped only about points away from its
// centroid (the kernel point as apex: positive) and one that is not star-shaped at all
// (the moment-fitted rule on its inside points: positive and exact all the same).
#include <gtest/gtest.h>

#include "shared/geometry/monomial_index.hpp"
#include "shared/geometry/polyhedron_moments.hpp"
#include "shared/quadrature/polyhedron_rule.hpp"
#include "tests/unit/polyhedra.hpp"

namespace altfem {
namespace {


void expect_exact(const Polyhedron& polyhedron, int strength, double tolerance = 1e-13) {
  const PolyhedronRule rule = polyhedron_rule(polyhedron, strength);
  const Eigen::VectorXd exact = polyhedron_moments(polyhedron, strength);
  const auto exponents = monomial_exponents(strength);
  for (Eigen::Index m = 0; m < exponents.rows(); ++m) {
    double sum = 0, magnitude = 0;
    for (Eigen::Index q = 0; q < rule.weights.size(); ++q) {
      const double value = std::pow(rule.points(q, 0), exponents(m, 0)) * std::pow(rule.points(q, 1), exponents(m, 1)) *
                           std::pow(rule.points(q, 2), exponents(m, 2));
      sum += rule.weights[q] * value;
      magnitude += std::abs(rule.weights[q] * value);
    }
    EXPECT_NEAR(sum, exact[m], tolerance * std::max(magnitude, 1.0)) << "monomial " << exponents.row(m);
  }
}

TEST(PolyhedronRule, ConvexCellIsExactWithPositiveWeights) {
  const Polyhedron cube = test::prism({{0, 0}, {1.3, 0}, {1.3, 1}, {0, 1}}, 0.7);
  for (int strength : {1, 3, 6}) expect_exact(cube, strength);
  EXPECT_TRUE(polyhedron_rule(cube, 3).positive);
}

TEST(PolyhedronRule, StarShapedNonConvexCellIsExactWithPositiveWeights) {
  const Polyhedron l_prism = test::l_prism();
  for (int strength : {1, 4}) expect_exact(l_prism, strength);
  EXPECT_TRUE(polyhedron_rule(l_prism, 4).positive);
}

TEST(PolyhedronRule, CellStarShapedAwayFromItsCentroidGetsPositiveWeights) {
  // A long thin L: its centroid lies in the long arm, behind the short arm's inner face;
  // the corner square [0, 0.5]² sees every face.
  const Polyhedron long_l = test::prism({{0, 0}, {4, 0}, {4, 0.5}, {0.5, 0.5}, {0.5, 1}, {0, 1}}, 0.7);
  for (int strength : {2, 4}) expect_exact(long_l, strength);
  EXPECT_TRUE(polyhedron_rule(long_l, 2).positive);
}

TEST(PolyhedronRule, CellThatIsNotStarShapedGetsAPositiveExactRule) {
  // A thin U: no point sees both arms' inner faces.
  const Polyhedron u_prism = test::prism({{0, 0}, {3, 0}, {3, 3}, {2.8, 3}, {2.8, 0.2}, {0.2, 0.2}, {0.2, 3}, {0, 3}}, 0.7);
  for (int strength : {2, 4}) {
    expect_exact(u_prism, strength, 1e-10);
    const PolyhedronRule rule = polyhedron_rule(u_prism, strength);
    EXPECT_TRUE(rule.positive);
    EXPECT_GT(rule.weights.minCoeff(), 0);
    // A basic feasible point: at most one point per moment.
    EXPECT_LE(rule.weights.size(), monomial_count(strength));
  }
}

}  // namespace
}  // namespace altfem
