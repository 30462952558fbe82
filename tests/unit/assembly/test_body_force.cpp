// Body-force load vectors f_(3b+i) = ∫ ρ a_i φ_b dV (issue #14, item 2): for a
// Lagrange basis (a partition of unity) they equal the old M·(a repeated per node);
// for a monomial basis on a box they equal ρ a_i × the exact moments.
#include <gtest/gtest.h>

#include <cmath>

#include "shared/quadrature/reference_rules.hpp"
#include "tests/unit/assembly/assembly_fixture.hpp"

namespace altfem {
namespace {

constexpr double density = 750;
const Eigen::Vector3d acceleration(0.3, -9.81, 1.7);

class BodyForceOfType : public ::testing::TestWithParam<ElementType> {};

TEST_P(BodyForceOfType, EqualsMassTimesRepeatedAcceleration) {
  const test::AssemblyProblem problem(GetParam(), {2, 3, 2}, MaterialModel::linear, density);
  SparseMatrix mass;
  problem.assembler->mass_matrix(mass);
  const Eigen::VectorXd repeated = acceleration.replicate(mass.rows() / 3, 1);
  const Eigen::VectorXd expected = mass * repeated;
  const Eigen::VectorXd load = problem.assembler->body_force(acceleration);
  EXPECT_LT((load - expected).norm(), 1e-12 * expected.norm());
  // Total force ρ V a (the distortion keeps the unit cube).
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(load(Eigen::seqN(i, load.size() / 3, 3)).sum(), density * acceleration[i], 1e-11 * density * 10);
}

INSTANTIATE_TEST_SUITE_P(ElasticAssembler, BodyForceOfType, ::testing::ValuesIn(test::all_element_types),
                         [](const auto& info) { return std::string(element_name(info.param)); });

// The 10 monomials x^p y^q z^r of total degree ≤ 2.
constexpr int exponents[10][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {2, 0, 0},
                                  {1, 1, 0}, {1, 0, 1}, {0, 2, 0}, {0, 1, 1}, {0, 0, 2}};

double monomial(int m, const Eigen::Vector3d& x) {
  return std::pow(x.x(), exponents[m][0]) * std::pow(x.y(), exponents[m][1]) * std::pow(x.z(), exponents[m][2]);
}
Eigen::RowVector3d monomial_gradient(int m, const Eigen::Vector3d& x) {
  Eigen::RowVector3d gradient = Eigen::RowVector3d::Zero();
  for (int d = 0; d < 3; ++d) {
    if (exponents[m][d] == 0) continue;
    gradient[d] = exponents[m][d];
    for (int e = 0; e < 3; ++e) gradient[d] *= std::pow(x[e], exponents[m][e] - (e == d ? 1 : 0));
  }
  return gradient;
}

TEST(BodyForce, MonomialBasisOnBoxGivesExactMoments) {
  // The box [0,2]×[0,1]×[0,3] as two elements [0,1] and [1,2] in x, both carrying the
  // same 10 global monomials (one element of the fixed size 10, summed twice), each
  // with a tensor Gauss rule exact for degree 3 (the monomials times the constant ρ a).
  const QuadratureRule rule = hex_rule(3);
  TabulatedElements elements;
  const std::vector<int> basis{0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
  for (int half = 0; half < 2; ++half) {
    const Eigen::Vector3d centre(half + 0.5, 0.5, 1.5), half_size(0.5, 0.5, 1.5);
    const auto points = rule.weights.size();
    std::vector<double> weights(points);
    Eigen::MatrixXd values(points, 10), gradients(points * 10, 3);
    for (Eigen::Index q = 0; q < points; ++q) {
      const Eigen::Vector3d x = centre + half_size.cwiseProduct(rule.points.row(q).transpose());
      weights[q] = rule.weights[q] * half_size.prod();
      for (int m = 0; m < 10; ++m) {
        values(q, m) = monomial(m, x);
        gradients.row(10 * q + m) = monomial_gradient(m, x);
      }
    }
    elements.add(basis, weights, values, gradients);
  }
  const auto material = make_material(MaterialModel::linear, 1e4, 0.3, density);
  const ElasticAssembler assembler(elements, {material.get()});
  const Eigen::VectorXd load = assembler.body_force(acceleration);
  ASSERT_EQ(load.size(), 30);
  for (int m = 0; m < 10; ++m) {
    // ∫_0^L s^p ds = L^(p+1)/(p+1) per axis, L = 2, 1, 3.
    const auto [p, q, r] = exponents[m];
    const double moment = std::pow(2.0, p + 1) / (p + 1) * (1.0 / (q + 1)) * std::pow(3.0, r + 1) / (r + 1);
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(load[3 * m + i], density * acceleration[i] * moment, 1e-12 * density * 10 * moment)
          << "monomial " << m << " component " << i;
  }
}

}  // namespace
}  // namespace altfem
