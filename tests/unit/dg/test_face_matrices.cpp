// DG face matrices by exact polygon moments (Kaufmann et al. 2009 eqs. (19)-(21),
// (24)-(26)) against the same integrals by a tensor Gauss rule that is exact for them,
// on an interior face between two differently centred and scaled elements and on a
// boundary face; and the properties the flux must have: symmetry, and no penalty for a
// field continuous across the face.
#include <gtest/gtest.h>

#include "dg/exact_element_matrices.hpp"
#include "dg/face_matrices.hpp"
#include "shared/geometry/polygon_moments.hpp"
#include "shared/quadrature/reference_rules.hpp"
#include "tests/unit/dg/lame_parameters.hpp"
#include "tests/unit/polyhedra.hpp"

namespace altfem::dg {
namespace {

constexpr double penalty = 7.0;

// The face x = 1, y ∈ [0, 1], z ∈ [0, 2] (counter-clockwise seen from +x).
Eigen::MatrixXd face_polygon() {
  Eigen::MatrixXd polygon(4, 3);
  polygon << 1, 0, 0, 1, 1, 0, 1, 1, 2, 1, 0, 2;
  return polygon;
}

// The face matrix by Gauss quadrature of the integrands of eqs. (24)-(26).
Eigen::MatrixXd gauss_face_matrix(const MonomialBasis& minus, const MonomialBasis* plus, Flux flux, int degree) {
  const QuadratureRule rule = quad_rule(2 * degree + 1);
  const Eigen::Vector3d normal = Eigen::Vector3d::UnitX();
  const int n = minus.size() + (plus ? plus->size() : 0);
  Eigen::MatrixXd matrix = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  Eigen::VectorXd values_minus, values_plus;
  Eigen::MatrixXd gradients_minus, gradients_plus;
  for (Eigen::Index q = 0; q < rule.weights.size(); ++q) {
    const Eigen::Vector3d x(1, 0.5 * (rule.points(q, 0) + 1), rule.points(q, 1) + 1);
    const double w = rule.weights[q] * 0.5;  // the face is [0,1] × [0,2]: Jacobian 0.5 · 1
    minus.evaluate(x, values_minus, gradients_minus);
    Eigen::VectorXd phi(n), sign(n);
    Eigen::MatrixXd grad(n, 3);
    phi.head(minus.size()) = values_minus;
    grad.topRows(minus.size()) = gradients_minus;
    sign.head(minus.size()).setOnes();
    if (plus) {
      plus->evaluate(x, values_plus, gradients_plus);
      phi.tail(plus->size()) = values_plus;
      grad.bottomRows(plus->size()) = gradients_plus;
      sign.tail(plus->size()).setConstant(-1);
    }
    const double average = plus ? 0.5 : 1.0;
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b)
        for (int i = 0; i < 3; ++i)
          for (int k = 0; k < 3; ++k) {
            double entry = i == k ? penalty * sign[a] * sign[b] * phi[a] * phi[b] : 0.0;
            if (flux == Flux::interior_penalty) {
              const auto traction = [&](int test, int trial, int ti, int tk) {  // (σ(φ_trial e_tk) n)_ti φ_test
                return phi[test] * ((ti == tk ? mu * grad.row(trial).dot(normal) : 0.0) +
                                    mu * normal[tk] * grad(trial, ti) + lambda * normal[ti] * grad(trial, tk));
              };
              entry -= average * (sign[a] * traction(a, b, i, k) + sign[b] * traction(b, a, k, i));
            }
            matrix(3 * a + i, 3 * b + k) += w * entry;
          }
  }
  return matrix;
}

class FaceOfDegree : public ::testing::TestWithParam<std::tuple<int, Flux>> {};

TEST_P(FaceOfDegree, InteriorFaceMatchesAnExactGaussRule) {
  const auto [degree, flux] = GetParam();
  const MonomialBasis minus(degree, Eigen::Vector3d(0.5, 0.5, 1), 2.4),
      plus(degree, Eigen::Vector3d(1.75, 0.5, 1), 2.9);
  const Eigen::MatrixXd exact =
      exact_face_matrix(face_polygon(), Eigen::Vector3d::UnitX(), minus, &plus, lambda, mu, penalty, flux);
  const Eigen::MatrixXd gauss = gauss_face_matrix(minus, &plus, flux, degree);
  EXPECT_LT((exact - gauss).cwiseAbs().maxCoeff(), 1e-12 * gauss.cwiseAbs().maxCoeff());
  EXPECT_LT((exact - exact.transpose()).cwiseAbs().maxCoeff(), 1e-12 * gauss.cwiseAbs().maxCoeff());
}

TEST_P(FaceOfDegree, BoundaryFaceMatchesAnExactGaussRule) {
  const auto [degree, flux] = GetParam();
  const MonomialBasis minus(degree, Eigen::Vector3d(0.5, 0.5, 1), 2.4);
  const Eigen::MatrixXd exact =
      exact_face_matrix(face_polygon(), Eigen::Vector3d::UnitX(), minus, nullptr, lambda, mu, penalty, flux);
  const Eigen::MatrixXd gauss = gauss_face_matrix(minus, nullptr, flux, degree);
  EXPECT_LT((exact - gauss).cwiseAbs().maxCoeff(), 1e-12 * gauss.cwiseAbs().maxCoeff());
}

INSTANTIATE_TEST_SUITE_P(ExactFaceMatrices, FaceOfDegree,
                         ::testing::Combine(::testing::Values(1, 2, 3),
                                            ::testing::Values(Flux::interior_penalty, Flux::babuska_zlamal)));

class BabuskaZlamalOfDegree : public ::testing::TestWithParam<int> {};

TEST_P(BabuskaZlamalOfDegree, AContinuousFieldPaysNoPenalty) {
  // The same affine field on both sides has no jump: the penalty part vanishes, so
  // the Babuška–Zlámal matrix annihilates it.
  const int degree = GetParam();
  const Flux flux = Flux::babuska_zlamal;
  const MonomialBasis minus(degree, Eigen::Vector3d(0.5, 0.5, 1), 2.4),
      plus(degree, Eigen::Vector3d(1.75, 0.5, 1), 2.9);
  const Eigen::MatrixXd matrix =
      exact_face_matrix(face_polygon(), Eigen::Vector3d::UnitX(), minus, &plus, lambda, mu, penalty, flux);
  Eigen::Matrix3d A;
  A << 0.1, 0.2, -0.1, 0.05, 0.3, 0.2, -0.2, 0.1, 0.4;
  const Eigen::Vector3d b(0.3, -0.1, 0.2);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(3 * (minus.size() + plus.size()));
  for (const auto& [basis, offset] : {std::pair{&minus, 0}, std::pair{&plus, minus.size()}}) {
    u.segment<3>(3 * offset) = A * basis->centre() + b;
    for (int d = 0; d < 3; ++d) u.segment<3>(3 * (offset + 1 + d)) = basis->scale() * A.col(d);
  }
  EXPECT_LT((matrix * u).cwiseAbs().maxCoeff(), 1e-12 * matrix.cwiseAbs().maxCoeff());
}

// Hansbo & Larson's split penalty (JumpPenalty): a constant jump c across the face costs
// ∫ cᵀ T c = area · (normal c_n² + tangential |c_t|²), each part by its own η.
TEST(JumpPenalty, SplitPenalisesNormalAndTangentialJumpsApart) {
  const MonomialBasis minus(1, Eigen::Vector3d(0.5, 0.5, 1), 2.4), plus(1, Eigen::Vector3d(1.75, 0.5, 1), 2.9);
  const JumpPenalty split{5.0, 2.0};
  const Eigen::MatrixXd matrix = exact_face_matrix(face_polygon(), Eigen::Vector3d::UnitX(), minus, &plus, lambda, mu,
                                                   split, Flux::babuska_zlamal);
  const double area = polygon_area_vector(face_polygon()).norm();
  for (int direction = 0; direction < 3; ++direction) {
    Eigen::VectorXd u = Eigen::VectorXd::Zero(matrix.rows());
    u[direction] = 1;  // the minus side's constant function, component `direction`; the plus side 0
    const double expected = (direction == 0 ? split.normal : split.tangential) * area;
    EXPECT_NEAR(u.dot(matrix * u), expected, 1e-12 * expected) << "component " << direction;
  }
}

// Consistency of interior penalty (the reason for its face terms, Kaufmann et al. §3.3):
// for an affine field u, the same on both elements, and a test function v on the minus
// element only, the DG form a(u, v) = ∫_K⁻ σ:ε(v) − ∫_f v·σn equals the traction work
// on the rest of ∂K⁻, ∫_{∂K⁻ \ f} v·σn — integrated here face by face.
TEST(InteriorPenalty, IsConsistentForAffineFields) {
  const int degree = 2;
  const Polyhedron box = test::box(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 1, 2));  // K⁻
  const MonomialBasis minus(degree, Eigen::Vector3d(0.5, 0.5, 1), 2.4),
      plus(degree, Eigen::Vector3d(1.75, 0.5, 1), 2.9);
  const Eigen::MatrixXd volume = exact_element_matrices(box, minus, lambda, mu, 1.0).stiffness;
  const Eigen::MatrixXd face = exact_face_matrix(face_polygon(), Eigen::Vector3d::UnitX(), minus, &plus, lambda, mu,
                                                 penalty, Flux::interior_penalty);
  Eigen::Matrix3d A;
  A << 0.1, 0.2, -0.1, 0.05, 0.3, 0.2, -0.2, 0.1, 0.4;
  const Eigen::Matrix3d strain = (A + A.transpose()) / 2;
  const Eigen::Matrix3d stress = 2 * mu * strain + lambda * strain.trace() * Eigen::Matrix3d::Identity();
  const int n = minus.size();
  Eigen::VectorXd u = Eigen::VectorXd::Zero(6 * n);
  for (const auto& [basis, offset] : {std::pair{&minus, 0}, std::pair{&plus, n}}) {
    u.segment<3>(3 * offset) = A * basis->centre();
    for (int d = 0; d < 3; ++d) u.segment<3>(3 * (offset + 1 + d)) = basis->scale() * A.col(d);
  }
  const Eigen::VectorXd residual = volume * u.head(3 * n) + (face * u).head(3 * n);

  Eigen::VectorXd expected = Eigen::VectorXd::Zero(3 * n);
  for (size_t f = 0; f < box.faces.size(); ++f) {
    if (f == 5) continue;  // {1, 3, 7, 5} is the shared face x = 1
    Eigen::MatrixXd polygon(4, 3);
    for (int k = 0; k < 4; ++k) polygon.row(k) = box.vertices.row(box.faces[f][k]);
    const Eigen::Vector3d normal = polygon_area_vector(polygon).normalized();
    const Eigen::VectorXd integrals = planar_polygon_moments(polygon, degree, minus.centre(), minus.scale());
    for (int a = 0; a < n; ++a) expected.segment<3>(3 * a) += integrals[a] * (stress * normal);
  }
  EXPECT_LT((residual - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
}

INSTANTIATE_TEST_SUITE_P(ExactFaceMatrices, BabuskaZlamalOfDegree, ::testing::Values(1, 2, 3));

}  // namespace
}  // namespace altfem::dg
