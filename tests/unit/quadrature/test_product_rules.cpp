#include "shared/quadrature/product_rules.hpp"

#include "quadrature_checks.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>

namespace altfem {
namespace {

using testing::Shape;

struct ProductRule {
  const char* name;
  std::function<QuadratureRule(int)> make;
  Shape shape;
  int dimension;
};

const ProductRule product_rules[] = {
    {"tensor_quad_rule", tensor_quad_rule, Shape::box, 2},
    {"tensor_hex_rule", tensor_hex_rule, Shape::box, 3},
    {"collapsed_triangle_rule", collapsed_triangle_rule, Shape::simplex, 2},
    {"collapsed_tet_rule", collapsed_tet_rule, Shape::simplex, 3},
};

TEST(ProductRules, ExactPositiveAndInteriorForStrengthZeroToFifteen) {
  for (const ProductRule& product : product_rules)
    for (int m = 0; m <= 15; ++m) {
      const QuadratureRule rule = product.make(m);
      ASSERT_EQ(rule.points.cols(), product.dimension) << product.name;
      EXPECT_GE(rule.strength, std::max(m, 1)) << product.name;
      EXPECT_TRUE(testing::exact_to_degree(rule, product.shape, m)) << product.name << " strength " << m;
      EXPECT_TRUE(testing::positive_and_interior(rule, product.shape)) << product.name << " strength " << m;
    }
}

TEST(ProductRules, StrengthThirty) {
  for (const ProductRule& product : product_rules) {
    const QuadratureRule rule = product.make(30);
    EXPECT_EQ(rule.points.rows(), product.dimension == 2 ? 16 * 16 : 16 * 16 * 16) << product.name;
    EXPECT_TRUE(testing::exact_to_degree(rule, product.shape, 30, 1e-12)) << product.name;
    EXPECT_TRUE(testing::positive_and_interior(rule, product.shape)) << product.name;
  }
}

TEST(ProductRules, PointCountIsMinimal) {
  // One point fewer per direction is not exact: strength 5 needs 3 points, 2 miss degree 4.
  EXPECT_EQ(collapsed_tet_rule(5).points.rows(), 27);
  EXPECT_EQ(tensor_hex_rule(5).points.rows(), 27);
  EXPECT_GT(testing::largest_monomial_error(collapsed_tet_rule(3), Shape::simplex, 4), 1e-6);
}

TEST(ProductRules, RejectNegativeStrength) {
  for (const ProductRule& product : product_rules)
    EXPECT_THROW(product.make(-1), std::invalid_argument) << product.name;
}

}  // namespace
}  // namespace altfem
