// Shape functions of every element type: nodal interpolation, partition of
// unity, exact reproduction of the element's polynomial space, and gradients
// against central finite differences.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "shared/element/reference_element.hpp"
#include "tests/unit/element/random_reference_points.hpp"

namespace altfem {
namespace {

using testing::all_element_types;
using testing::random_reference_points;

/// The monomial exponents each type must reproduce, listed here independently of
/// shared/element/polynomial_space.cpp.
std::vector<Eigen::Vector3i> expected_space(ElementType type) {
  const int k = element_degree(type);
  std::vector<Eigen::Vector3i> space;
  for (int a = 0; a <= 3; ++a)
    for (int b = 0; b <= 3; ++b)
      for (int c = 0; c <= 3; ++c) {
        const Eigen::Vector3i e(a, b, c);
        const bool tensor = e.maxCoeff() <= k;  // Q_k
        const bool total = e.sum() <= k;        // P_k
        if (element_shape(type) == ElementShape::tetrahedron ? total : type == ElementType::hex20 ? total : tensor)
          space.push_back(e);
      }
  if (type == ElementType::hex20)  // the serendipity extras beyond P_2
    for (const Eigen::Vector3i& extra :
         {Eigen::Vector3i(2, 1, 0), Eigen::Vector3i(2, 0, 1), Eigen::Vector3i(1, 2, 0), Eigen::Vector3i(0, 2, 1),
          Eigen::Vector3i(1, 0, 2), Eigen::Vector3i(0, 1, 2), Eigen::Vector3i(1, 1, 1), Eigen::Vector3i(2, 1, 1),
          Eigen::Vector3i(1, 2, 1), Eigen::Vector3i(1, 1, 2)})
      space.push_back(extra);
  return space;
}

double monomial(const Eigen::Vector3i& e, const Eigen::Vector3d& x) {
  return std::pow(x[0], e[0]) * std::pow(x[1], e[1]) * std::pow(x[2], e[2]);
}

Eigen::Vector3d monomial_gradient(const Eigen::Vector3i& e, const Eigen::Vector3d& x) {
  Eigen::Vector3d gradient;
  for (int d = 0; d < 3; ++d) {
    Eigen::Vector3i lowered = e;
    lowered[d] = std::max(e[d] - 1, 0);
    gradient[d] = e[d] * monomial(lowered, x);
  }
  return gradient;
}

TEST(ReferenceElement, KroneckerDeltaAtTheNodes) {
  for (ElementType type : all_element_types) {
    const ReferenceElement& element = reference_element(type);
    const int n = element.node_count();
    Eigen::MatrixXd table(n, n);  // row i: all shape functions at node i
    Eigen::VectorXd values(n);
    for (int i = 0; i < n; ++i) {
      element.evaluate(element.nodes().row(i).transpose(), values);
      table.row(i) = values.transpose();
    }
    EXPECT_LT((table - Eigen::MatrixXd::Identity(n, n)).cwiseAbs().maxCoeff(), 1e-12) << element_name(type);
  }
}

TEST(ReferenceElement, PartitionOfUnityAndGradientsSumToZero) {
  for (ElementType type : all_element_types) {
    const ReferenceElement& element = reference_element(type);
    Eigen::VectorXd values(element.node_count());
    Eigen::MatrixXd gradients(element.node_count(), 3);
    for (const Eigen::Vector3d& xi : random_reference_points(type, 20, 7)) {
      element.evaluate(xi, values);
      element.evaluate_gradients(xi, gradients);
      EXPECT_NEAR(values.sum(), 1.0, 1e-13) << element_name(type);
      EXPECT_LT(gradients.colwise().sum().norm(), 1e-12) << element_name(type);
    }
  }
}

TEST(ReferenceElement, ReproducesEveryMonomialOfItsSpaceWithGradients) {
  for (ElementType type : all_element_types) {
    const ReferenceElement& element = reference_element(type);
    const std::vector<Eigen::Vector3i> space = expected_space(type);
    ASSERT_EQ(static_cast<int>(space.size()), element.node_count()) << element_name(type);
    Eigen::VectorXd values(element.node_count());
    Eigen::MatrixXd gradients(element.node_count(), 3);
    for (const Eigen::Vector3i& e : space) {
      Eigen::VectorXd nodal(element.node_count());
      for (int i = 0; i < element.node_count(); ++i) nodal[i] = monomial(e, element.nodes().row(i).transpose());
      // Points slightly outside the domain too: reproduction is an identity of polynomials.
      for (const Eigen::Vector3d& xi : random_reference_points(type, 10, 11, -0.2)) {
        element.evaluate(xi, values);
        element.evaluate_gradients(xi, gradients);
        EXPECT_NEAR(values.dot(nodal), monomial(e, xi), 1e-12) << element_name(type) << " monomial " << e.transpose();
        EXPECT_LT((gradients.transpose() * nodal - monomial_gradient(e, xi)).norm(), 1e-11)
            << element_name(type) << " monomial " << e.transpose();
      }
    }
  }
}

TEST(ReferenceElement, Hex20IsSerendipityNotTriquadratic) {
  // x²y² is in Q_2 but not in S_2: Hex20 must not reproduce it, Hex27 must.
  const Eigen::Vector3i e(2, 2, 0);
  const Eigen::Vector3d xi(0.3, -0.6, 0.2);
  for (ElementType type : {ElementType::hex20, ElementType::hex27}) {
    const ReferenceElement& element = reference_element(type);
    Eigen::VectorXd values(element.node_count()), nodal(element.node_count());
    for (int i = 0; i < element.node_count(); ++i) nodal[i] = monomial(e, element.nodes().row(i).transpose());
    element.evaluate(xi, values);
    const double error = std::abs(values.dot(nodal) - monomial(e, xi));
    if (type == ElementType::hex20) EXPECT_GT(error, 1e-3);
    else EXPECT_LT(error, 1e-13);
  }
}

// Central differences (step 1e-6) of a tabulation ξ ↦ #nodes × c along each reference
// axis: column c·d + j of the result holds ∂(column j)/∂ξ_d.
template <typename Tabulate>
Eigen::MatrixXd central_differences(int nodes, int columns, const Eigen::Vector3d& xi, Tabulate tabulate) {
  const double h = 1e-6;
  Eigen::MatrixXd plus(nodes, columns), minus(nodes, columns), result(nodes, 3 * columns);
  for (int d = 0; d < 3; ++d) {
    tabulate(Eigen::Vector3d(xi + h * Eigen::Vector3d::Unit(d)), plus);
    tabulate(Eigen::Vector3d(xi - h * Eigen::Vector3d::Unit(d)), minus);
    result.middleCols(columns * d, columns) = (plus - minus) / (2.0 * h);
  }
  return result;
}

// Gradients against differences of the values, Hessians against differences of the
// gradients (column 3d + e of those is ∂²/∂ξ_d∂ξ_e, the Hessians' layout; symmetric).
TEST(ReferenceElement, GradientsAndHessiansMatchCentralFiniteDifferences) {
  for (ElementType type : all_element_types) {
    const ReferenceElement& element = reference_element(type);
    const int n = element.node_count();
    Eigen::MatrixXd gradients(n, 3), hessians(n, 9);
    for (const Eigen::Vector3d& xi : random_reference_points(type, 10, 13)) {
      element.evaluate_gradients(xi, gradients);
      element.evaluate_hessians(xi, hessians);
      const Eigen::MatrixXd value_differences = central_differences(
          n, 1, xi, [&](const Eigen::Vector3d& at, Eigen::MatrixXd& values) { element.evaluate(at, values.col(0)); });
      const Eigen::MatrixXd gradient_differences = central_differences(
          n, 3, xi,
          [&](const Eigen::Vector3d& at, Eigen::MatrixXd& values) { element.evaluate_gradients(at, values); });
      for (const auto& [exact, differences] :
           {std::pair{&gradients, &value_differences}, std::pair{&hessians, &gradient_differences}}) {
        const double scale = std::max(1.0, exact->cwiseAbs().maxCoeff());
        EXPECT_LT((*differences - *exact).cwiseAbs().maxCoeff(), 1e-7 * scale)
            << element_name(type) << " at " << xi.transpose() << ", " << exact->cols() << " columns";
      }
    }
  }
}

TEST(ReferenceElement, HessiansReproduceEveryMonomialsSecondDerivatives) {
  for (ElementType type : all_element_types) {
    const ReferenceElement& element = reference_element(type);
    Eigen::MatrixXd hessians(element.node_count(), 9);
    for (const Eigen::Vector3i& e : expected_space(type)) {
      Eigen::VectorXd nodal(element.node_count());
      for (int i = 0; i < element.node_count(); ++i) nodal[i] = monomial(e, element.nodes().row(i).transpose());
      for (const Eigen::Vector3d& xi : random_reference_points(type, 5, 19, -0.2)) {
        element.evaluate_hessians(xi, hessians);
        for (int d = 0; d < 3; ++d)
          for (int c = 0; c < 3; ++c) {
            // ∂_d ∂_c ξ^e by hand.
            Eigen::Vector3i lowered = e;
            double factor = lowered[d]--;
            factor *= lowered[c]--;
            const double exact = factor == 0.0 ? 0.0 : factor * monomial(lowered, xi);
            EXPECT_NEAR(hessians.col(3 * d + c).dot(nodal), exact, 1e-10)
                << element_name(type) << " monomial " << e.transpose() << " d " << d << " c " << c;
          }
      }
    }
  }
}

// The points as the rows of one matrix (#points × 3), as the batched evaluations take them.
Eigen::MatrixXd as_rows(const std::vector<Eigen::Vector3d>& points) {
  Eigen::MatrixXd rows(static_cast<Eigen::Index>(points.size()), 3);
  for (size_t q = 0; q < points.size(); ++q) rows.row(static_cast<Eigen::Index>(q)) = points[q].transpose();
  return rows;
}

// The batched evaluation (one product over all points) is the pointwise one, column by
// column: only the summation order of the products may differ.
TEST(ReferenceElement, EvaluationAtManyPointsEqualsOnePointAtATime) {
  for (ElementType type : all_element_types) {
    const ReferenceElement& element = reference_element(type);
    const std::vector<Eigen::Vector3d> points = random_reference_points(type, 37, 41);
    const Eigen::MatrixXd stacked = as_rows(points);
    Eigen::MatrixXd values;
    std::array<Eigen::MatrixXd, 3> gradients;
    element.evaluate_at(stacked, values);
    element.evaluate_gradients_at(stacked, gradients);
    ASSERT_EQ(values.rows(), stacked.rows());
    ASSERT_EQ(values.cols(), element.node_count());
    Eigen::VectorXd one(element.node_count());
    Eigen::MatrixXd one_gradients(element.node_count(), 3);
    for (size_t q = 0; q < points.size(); ++q) {
      const auto row = static_cast<Eigen::Index>(q);
      element.evaluate(points[q], one);
      element.evaluate_gradients(points[q], one_gradients);
      EXPECT_LT((values.row(row).transpose() - one).cwiseAbs().maxCoeff(), 1e-13) << element_name(type);
      for (int j = 0; j < 3; ++j)
        EXPECT_LT((gradients[j].row(row).transpose() - one_gradients.col(j)).cwiseAbs().maxCoeff(), 1e-12)
            << element_name(type) << " ∂/∂ξ_" << j;
    }
  }
}

// integrate_products sums all points' products at once: it must equal the sums of the
// basis values' own products one point at a time, for any points and weights.
TEST(ReferenceElement, IntegratedProductsEqualTheSumsOfTheValuesProducts) {
  for (ElementType type : all_element_types) {
    const ReferenceElement& element = reference_element(type);
    const std::vector<Eigen::Vector3d> points = random_reference_points(type, 53, 7);
    const Eigen::MatrixXd stacked = as_rows(points);
    std::srand(11);
    const Eigen::VectorXd weights = Eigen::VectorXd::Random(stacked.rows());
    const int n = element.node_count();
    Eigen::MatrixXd expected_products = Eigen::MatrixXd::Zero(n, n);
    Eigen::VectorXd expected_integrals = Eigen::VectorXd::Zero(n), value(n);
    for (size_t q = 0; q < points.size(); ++q) {
      element.evaluate(points[q], value);
      expected_products += weights[static_cast<Eigen::Index>(q)] * value * value.transpose();
      expected_integrals += weights[static_cast<Eigen::Index>(q)] * value;
    }
    Eigen::MatrixXd products;
    Eigen::VectorXd integrals;
    element.integrate_products(stacked, weights, products, integrals);
    // Within round-off of the sums' size, Σ|w|.
    const double scale = weights.cwiseAbs().sum();
    EXPECT_LT((products - expected_products).cwiseAbs().maxCoeff(), 1e-14 * scale) << element_name(type);
    EXPECT_LT((integrals - expected_integrals).cwiseAbs().maxCoeff(), 1e-14 * scale) << element_name(type);
    EXPECT_EQ(products, products.transpose()) << element_name(type);
  }
}

TEST(ReferenceElement, ContainsItsDomainAndNothingElse) {
  const ReferenceElement& tet = reference_element(ElementType::tet10);
  EXPECT_TRUE(tet.contains(Eigen::Vector3d(0.25, 0.25, 0.25), 0.0));
  EXPECT_TRUE(tet.contains(Eigen::Vector3d(1.0, 0.0, 0.0), 0.0));
  EXPECT_FALSE(tet.contains(Eigen::Vector3d(0.5, 0.5, 0.1), 0.0));
  EXPECT_TRUE(tet.contains(Eigen::Vector3d(0.5, 0.5, 0.1), 0.11));
  EXPECT_FALSE(tet.contains(Eigen::Vector3d(-1e-6, 0.2, 0.2), 1e-8));
  EXPECT_TRUE(tet.centroid().isApprox(Eigen::Vector3d::Constant(0.25)));

  const ReferenceElement& hex = reference_element(ElementType::hex27);
  EXPECT_TRUE(hex.contains(Eigen::Vector3d(1.0, -1.0, 0.3), 0.0));
  EXPECT_FALSE(hex.contains(Eigen::Vector3d(1.0 + 1e-6, 0.0, 0.0), 1e-8));
  EXPECT_TRUE(hex.contains(Eigen::Vector3d(1.0 + 1e-9, 0.0, 0.0), 1e-8));
  EXPECT_TRUE(hex.centroid().isZero());
}

}  // namespace
}  // namespace altfem
