// DG element matrices by exact moment integration (Kaufmann et al. 2009 §5): against a
// tensor Gauss rule that is exact for the same polynomials on a box, and on a
// non-convex L-shaped prism against what linear elasticity must give — zero force for
// rigid motions and the exact energy V (μ ε:ε + λ/2 (tr ε)²) of a linear field.
#include <gtest/gtest.h>

#include "dg/exact_element_matrices.hpp"
#include "shared/quadrature/reference_rules.hpp"
#include "tests/unit/dg/lame_parameters.hpp"
#include "tests/unit/polyhedra.hpp"

namespace altfem::dg {
namespace {

constexpr double density = 3.0;

class EveryDegree : public ::testing::TestWithParam<int> {};

TEST_P(EveryDegree, MatchesAnExactGaussRuleOnABox) {
  const int k = GetParam();
  const Eigen::Vector3d low(0.5, -1, 2), high(1.7, 0.3, 2.9);
  const MonomialBasis basis(k, (low + high) / 2, (high - low).norm());
  const ElementMatrices exact = exact_element_matrices(test::box(low, high), basis, lambda, mu, density);
  const QuadratureRule rule = hex_rule(2 * k + 1);
  const Eigen::Vector3d half = (high - low) / 2;
  const int n = basis.size();
  Eigen::MatrixXd stiffness = Eigen::MatrixXd::Zero(3 * n, 3 * n), mass = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd values;
  Eigen::MatrixXd gradients;
  for (Eigen::Index q = 0; q < rule.weights.size(); ++q) {
    const Eigen::Vector3d x = (low + high) / 2 + half.cwiseProduct(rule.points.row(q).transpose());
    const double w = rule.weights[q] * half.prod();
    basis.evaluate(x, values, gradients);
    mass += w * density * values * values.transpose();
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b)
        for (int i = 0; i < 3; ++i)
          for (int c = 0; c < 3; ++c)
            stiffness(3 * a + i, 3 * b + c) +=
                w * ((i == c ? mu * gradients.row(a).dot(gradients.row(b)) : 0.0) +
                     mu * gradients(a, c) * gradients(b, i) + lambda * gradients(a, i) * gradients(b, c));
  }
  EXPECT_LT((exact.mass - mass).cwiseAbs().maxCoeff(), 1e-12 * mass.cwiseAbs().maxCoeff());
  EXPECT_LT((exact.stiffness - stiffness).cwiseAbs().maxCoeff(), 1e-12 * stiffness.cwiseAbs().maxCoeff());
}

// The coefficients of u(x) = A x + b in a degree-k monomial basis: u(c) on 1, h A e_d on ξ_d.
Eigen::VectorXd linear_field(const MonomialBasis& basis, const Eigen::Matrix3d& A, const Eigen::Vector3d& b) {
  Eigen::VectorXd u = Eigen::VectorXd::Zero(3 * basis.size());
  u.segment<3>(0) = A * basis.centre() + b;
  for (int d = 0; d < 3; ++d) u.segment<3>(3 * (1 + d)) = basis.scale() * A.col(d);
  return u;
}

TEST_P(EveryDegree, RigidMotionsCostNothingAndLinearFieldsTheExactEnergyOnANonConvexElement) {
  const Polyhedron element = test::l_prism(Eigen::Vector3d(5, -3, 0));  // away from the origin
  const double volume = 2.1;
  const MonomialBasis basis(GetParam(), Eigen::Vector3d(5.8, -2.2, 0.35), 2.5);
  const ElementMatrices matrices = exact_element_matrices(element, basis, lambda, mu, density);
  EXPECT_NEAR(matrices.mass(0, 0), density * volume, 1e-12);
  EXPECT_NEAR(matrices.integrals[0], volume, 1e-12);

  Eigen::Matrix3d skew;
  skew << 0, -0.3, 0.2, 0.3, 0, -0.1, -0.2, 0.1, 0;
  const double scale = matrices.stiffness.cwiseAbs().maxCoeff();
  EXPECT_LT((matrices.stiffness * linear_field(basis, Eigen::Matrix3d::Zero(), {1, 2, 3})).cwiseAbs().maxCoeff(),
            1e-12 * scale);
  EXPECT_LT((matrices.stiffness * linear_field(basis, skew, {0.5, 0, 0})).cwiseAbs().maxCoeff(), 1e-12 * scale);

  Eigen::Matrix3d A;
  A << 0.1, 0.02, -0.03, 0.04, -0.05, 0.01, 0.0, 0.03, 0.07;
  const Eigen::Matrix3d strain = (A + A.transpose()) / 2;
  const double energy_density =
      mu * (strain.array() * strain.array()).sum() + lambda / 2 * strain.trace() * strain.trace();
  const Eigen::VectorXd u = linear_field(basis, A, {0.1, 0.2, 0.3});
  EXPECT_NEAR(0.5 * u.dot(matrices.stiffness * u), volume * energy_density, 1e-12 * volume * energy_density);
}

INSTANTIATE_TEST_SUITE_P(ExactElementMatrices, EveryDegree, ::testing::Values(1, 2, 3));

TEST(MonomialBasis, GradientsDifferentiateTheValues) {
  const MonomialBasis basis(3, Eigen::Vector3d(1, 2, 3), 0.7);
  const Eigen::Vector3d x(1.2, 1.9, 3.3);
  Eigen::VectorXd values, plus, minus;
  Eigen::MatrixXd gradients, unused;
  basis.evaluate(x, values, gradients);
  ASSERT_EQ(values.size(), 20);
  EXPECT_DOUBLE_EQ(values[0], 1.0);
  for (int d = 0; d < 3; ++d) {
    basis.evaluate(x + 1e-6 * Eigen::Vector3d::Unit(d), plus, unused);
    basis.evaluate(x - 1e-6 * Eigen::Vector3d::Unit(d), minus, unused);
    EXPECT_LT(((plus - minus) / 2e-6 - gradients.col(d)).cwiseAbs().maxCoeff(), 1e-8);
  }
}

}  // namespace
}  // namespace altfem::dg
