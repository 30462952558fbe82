#include "shared/quadrature/reference_rules.hpp"

#include "quadrature_checks.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>

namespace altfem {
namespace {

using testing::Shape;

struct SelectedRule {
  const char* name;
  std::function<QuadratureRule(int)> make;
  Shape shape;
};

const SelectedRule selected_rules[] = {
    {"quad_rule", quad_rule, Shape::box},
    {"triangle_rule", triangle_rule, Shape::simplex},
    {"hex_rule", hex_rule, Shape::box},
    {"tet_rule", tet_rule, Shape::simplex},
};

TEST(ReferenceRules, ExactPositiveAndInteriorForStrengthZeroToFifteen) {
  for (const SelectedRule& selected : selected_rules)
    for (int m = 0; m <= 15; ++m) {
      const QuadratureRule rule = selected.make(m);
      EXPECT_GE(rule.strength, std::max(m, 1)) << selected.name;
      EXPECT_TRUE(testing::exact_to_degree(rule, selected.shape, m)) << selected.name << " strength " << m;
      EXPECT_TRUE(testing::positive_and_interior(rule, selected.shape)) << selected.name << " strength " << m;
    }
}

TEST(ReferenceRules, SmallestShippedTableOfSufficientStrength) {
  EXPECT_EQ(tet_rule(0).points.rows(), 1);
  EXPECT_EQ(tet_rule(4).points.rows(), 14);  // no strength-4 table: the 5-14 one
  EXPECT_EQ(tet_rule(4).strength, 5);
  EXPECT_EQ(tet_rule(10).points.rows(), 81);
  EXPECT_EQ(hex_rule(11).points.rows(), 90);
  EXPECT_EQ(triangle_rule(3).points.rows(), 6);  // 4-6, although the (asymmetric) collapsed rule has 4
  EXPECT_EQ(quad_rule(3).points.rows(), 4);      // 3-4, a tie with the tensor rule
  EXPECT_EQ(triangle_rule(20).points.rows(), 79);
  EXPECT_EQ(quad_rule(20).points.rows(), 85);  // 21-85
}

TEST(ReferenceRules, SkipsTablesWithBoundaryPoints) {
  // hex 3-6 has its points at the face centres: strength 2 and 3 take the (symmetric)
  // 2×2×2 Gauss rule, smaller than the next table (5-14). tri 16-55 has points on the edges.
  EXPECT_EQ(hex_rule(2).points.rows(), 8);
  EXPECT_EQ(hex_rule(3).points.rows(), 8);
  EXPECT_EQ(hex_rule(4).points.rows(), 14);
  EXPECT_EQ(triangle_rule(16).points.rows(), 60);  // 17-60
  EXPECT_EQ(triangle_rule(15).points.rows(), 49);  // 15-49
}

TEST(ReferenceRules, FallsBackToProductRulesAboveTheTables) {
  // Past the last table the rule is the product rule, point for point.
  const std::pair<std::function<QuadratureRule(int)>, std::function<QuadratureRule(int)>> pairs[] = {
      {tet_rule, collapsed_tet_rule},
      {hex_rule, tensor_hex_rule},
      {triangle_rule, collapsed_triangle_rule},
      {quad_rule, tensor_quad_rule}};
  const int first_beyond_tables[] = {11, 12, 21, 22};
  for (int i = 0; i < 4; ++i) {
    const QuadratureRule selected = pairs[i].first(first_beyond_tables[i]);
    const QuadratureRule product = pairs[i].second(first_beyond_tables[i]);
    EXPECT_EQ(selected.points, product.points) << i;
    EXPECT_EQ(selected.weights, product.weights) << i;
  }
  EXPECT_EQ(tet_rule(11).points.rows(), 6 * 6 * 6);
  EXPECT_EQ(tet_rule(30).points.rows(), 16 * 16 * 16);
}

TEST(ReferenceRules, ReferenceRuleMatchesNamedFunctions) {
  EXPECT_EQ(reference_rule(ReferenceDomain::tetrahedron, 7).points, tet_rule(7).points);
  EXPECT_EQ(reference_rule(ReferenceDomain::quadrilateral, 3).weights, quad_rule(3).weights);
}

TEST(ReferenceRules, RejectNegativeStrength) {
  for (const SelectedRule& selected : selected_rules)
    EXPECT_THROW(selected.make(-1), std::invalid_argument) << selected.name;
}

}  // namespace
}  // namespace altfem
