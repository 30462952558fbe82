// Rules on polyhedra by cone decomposition: every monomial up to the strength against the
// exact moments (shared/geometry/polyhedron_moments), on a convex cell, a star-shaped
// non-convex one (positive weights), one star-shaped only about points away from its
// centroid (the kernel point as apex: positive) and one that is not star-shaped at all
// (the moment-fitted rule on its inside points: positive and exact all the same), also
// when its faces are many, or with at least as many points as asked (spread over its
// inside points instead of one per moment); and the simplified rules of cells of many facets (at most one
// point per moment, exact all the same).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "shared/geometry/monomial_index.hpp"
#include "shared/geometry/polyhedron_moments.hpp"
#include "shared/quadrature/polyhedron_rule.hpp"
#include "tests/unit/polyhedra.hpp"

namespace altfem {
namespace {

void expect_exact(const PolyhedronRule& rule, const Polyhedron& polyhedron, int strength, double tolerance = 1e-13) {
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

void expect_exact(const Polyhedron& polyhedron, int strength, double tolerance = 1e-13) {
  expect_exact(polyhedron_rule(polyhedron, strength), polyhedron, strength, tolerance);
}

// The outline with every edge split into `pieces` collinear segments: as many side faces
// as a cut cell of a detailed surface has facets.
std::vector<Eigen::Vector2d> refined(const std::vector<Eigen::Vector2d>& outline, int pieces) {
  std::vector<Eigen::Vector2d> result;
  for (size_t k = 0; k < outline.size(); ++k)
    for (int piece = 0; piece < pieces; ++piece)
      result.push_back(outline[k] + (outline[(k + 1) % outline.size()] - outline[k]) * piece / pieces);
  return result;
}

const std::vector<Eigen::Vector2d> u_outline{{0, 0},     {3, 0},     {3, 3},   {2.8, 3},
                                             {2.8, 0.2}, {0.2, 0.2}, {0.2, 3}, {0, 3}};

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
  const Polyhedron u_prism = test::prism(u_outline, 0.7);
  for (int strength : {2, 4}) {
    expect_exact(u_prism, strength, 1e-10);
    const PolyhedronRule rule = polyhedron_rule(u_prism, strength);
    EXPECT_TRUE(rule.positive);
    EXPECT_GT(rule.weights.minCoeff(), 0);
    // A basic feasible point: at most one point per moment.
    EXPECT_LE(rule.weights.size(), monomial_count(strength));
  }
}

TEST(PolyhedronRule, CellOfManyFacesThatIsNotStarShapedGetsAPositiveExactRule) {
  // 8 × 60 side faces: the moment fit must not need every candidate of every cone
  // tetrahedron (it tries growing batches of them).
  const Polyhedron u_prism = test::prism(refined(u_outline, 60), 0.7);
  const PolyhedronRule rule = polyhedron_rule(u_prism, 4);
  expect_exact(rule, u_prism, 4, 1e-10);
  EXPECT_TRUE(rule.positive);
  EXPECT_LE(rule.weights.size(), monomial_count(4));
}

TEST(PolyhedronRule, CellThatIsNotStarShapedGetsAtLeastTheRequiredPointsPositiveAndExact) {
  // A harmonic cell with hundreds of nodes needs more points than moments: the U of 8 × 60
  // side faces (482 vertices) asked for twice as many points as it has vertices.
  const Polyhedron u_prism = test::prism(refined(u_outline, 60), 0.7);
  const int vertices = static_cast<int>(u_prism.vertices.rows());
  for (int strength : {2, 4}) {
    const PolyhedronRule rule = polyhedron_rule(u_prism, strength, 2 * vertices);
    EXPECT_GE(rule.weights.size(), 2 * vertices);
    EXPECT_GT(rule.weights.minCoeff(), 0);
    EXPECT_TRUE(rule.positive);
    expect_exact(rule, u_prism, strength, 1e-12);
    // Every point inside the U: within its bounding box and off the gap between its arms
    // (0.2 < x < 2.8, y > 0.2).
    for (Eigen::Index q = 0; q < rule.points.rows(); ++q) {
      const Eigen::Vector3d x = rule.points.row(q).transpose();
      EXPECT_TRUE(x.x() >= 0 && x.x() <= 3 && x.y() >= 0 && x.y() <= 3 && x.z() >= 0 && x.z() <= 0.7) << x.transpose();
      EXPECT_FALSE(x.x() > 0.2 && x.x() < 2.8 && x.y() > 0.2) << x.transpose();
    }
  }
}

TEST(PolyhedronRule, SimplifiedRuleOfACellOfManyFacetsHasOnePointPerMomentAtMost) {
  // A 240-gon prism: 242 faces, 956 tetrahedra in the cone rule.
  std::vector<Eigen::Vector2d> circle;
  for (int k = 0; k < 240; ++k) circle.emplace_back(std::cos(2 * M_PI * k / 240), 0.6 * std::sin(2 * M_PI * k / 240));
  const Polyhedron disc = test::prism(circle, 0.3, Eigen::Vector3d(0.4, -0.2, 0.1));
  for (int strength : {2, 4}) {
    const PolyhedronRule cone = polyhedron_rule(disc, strength);
    const PolyhedronRule simplified = simplified_polyhedron_rule(disc, strength, SimplificationMethod::caratheodory);
    EXPECT_GT(cone.weights.size(), 100 * monomial_count(strength));
    EXPECT_LE(simplified.weights.size(), monomial_count(strength));
    EXPECT_GT(simplified.weights.minCoeff(), 0);
    expect_exact(simplified, disc, strength, 1e-11);
  }
  // No method: the cone rule itself.
  EXPECT_EQ(simplified_polyhedron_rule(disc, 2, std::nullopt).weights.size(), polyhedron_rule(disc, 2).weights.size());
  // A rule of negative weights is no start for the simplifier: the U keeps its own.
  const Polyhedron u_prism = test::prism(u_outline, 0.7);
  EXPECT_EQ(simplified_polyhedron_rule(u_prism, 2, SimplificationMethod::caratheodory).weights.size(),
            polyhedron_rule(u_prism, 2).weights.size());
}

}  // namespace
}  // namespace altfem
