// polygon_moments_2d against the rectangle product formula and triangle-fan quadrature
// on non-convex polygons; planar_polygon_moments against the same polygons placed in 3D
// (a plane z = const, and a generic rotation with quadrature on the 2D polygon).
#include "shared/geometry/polygon_moments.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <stdexcept>

#include "shared/geometry/monomial_index.hpp"
#include "tests/unit/geometry/moments_reference.hpp"

namespace altfem {
namespace {

using test::expect_moments_near;

constexpr double tolerance = 1e-12;
constexpr int degree = 10;

// A 7-pointed star, star-shaped about `centre`, with radii far apart: sharply non-convex.
Eigen::MatrixXd star(const Eigen::Vector2d& centre) {
  Eigen::MatrixXd result(14, 2);
  for (int i = 0; i < 14; ++i) {
    const double angle = M_PI * i / 7 + 0.1, radius = i % 2 == 0 ? 1.3 : 0.3;
    result.row(i) << centre.x() + radius * std::cos(angle), centre.y() + radius * std::sin(angle);
  }
  return result;
}

Eigen::Vector3d embedded(const Eigen::VectorXd& point, const Eigen::Matrix3d& rotation,
                         const Eigen::Vector3d& translation) {
  return rotation * Eigen::Vector3d(point(0), point(1), 0.0) + translation;
}

TEST(PolygonMoments2d, RectangleFarFromOriginMatchesProductFormula) {
  const Eigen::Vector2d low(999.99, -500.0), high(1000.0, -499.995);
  Eigen::MatrixXd rectangle(4, 2);
  rectangle << low.x(), low.y(), high.x(), low.y(), high.x(), high.y(), low.x(), high.y();
  expect_moments_near(polygon_moments_2d(rectangle, degree), test::rectangle_moments(low, high, degree), tolerance);
}

TEST(PolygonMoments2d, CentredMomentsOfRectangle) {
  const Eigen::Vector2d low(-1.0, 2.0), high(3.0, 2.5), centre(0.5, 2.0);
  const double scale = 2.0;
  Eigen::MatrixXd rectangle(4, 2);
  rectangle << low.x(), low.y(), high.x(), low.y(), high.x(), high.y(), low.x(), high.y();
  test::ReferenceMoments reference = test::rectangle_moments((low - centre) / scale, (high - centre) / scale, degree);
  reference.exact *= scale * scale;
  reference.absolute *= scale * scale;
  expect_moments_near(polygon_moments_2d(rectangle, degree, centre, scale), reference, tolerance);
}

TEST(PolygonMoments2d, NonConvexStarMatchesTriangleFan) {
  const Eigen::Vector2d centre(-2.0, 0.7);
  const Eigen::MatrixXd polygon = star(centre);
  const auto identity = [](const Eigen::VectorXd& x) { return x; };
  expect_moments_near(polygon_moments_2d(polygon, degree),
                      test::fan_quadrature_moments(polygon, centre, degree, identity, monomial_count_2d(degree)),
                      tolerance);
}

TEST(PolygonMoments2d, ClockwiseGivesNegatedMoments) {
  const Eigen::MatrixXd polygon = star({0.3, 0.2});
  const Eigen::MatrixXd reversed = polygon.colwise().reverse();
  const Eigen::VectorXd forward = polygon_moments_2d(polygon, 6);
  EXPECT_GT(forward(0), 0.0);
  EXPECT_LE((polygon_moments_2d(reversed, 6) + forward).cwiseAbs().maxCoeff(), 1e-14 * forward.cwiseAbs().maxCoeff());
}

TEST(PlanarPolygonMoments, PolygonInPlaneZEqualsConstant) {
  const Eigen::MatrixXd polygon = star({0.4, -0.1});
  const double height = 1.7;
  Eigen::MatrixXd lifted(polygon.rows(), 3);
  lifted << polygon, Eigen::VectorXd::Constant(polygon.rows(), height);
  const Eigen::VectorXd flat = polygon_moments_2d(polygon, degree);
  const auto exponents = monomial_exponents(degree);
  test::ReferenceMoments reference{Eigen::VectorXd(exponents.rows()), Eigen::VectorXd(exponents.rows())};
  for (Eigen::Index row = 0; row < exponents.rows(); ++row) {
    reference.exact(row) =
        flat(monomial_index_2d(exponents(row, 0), exponents(row, 1))) * std::pow(height, exponents(row, 2));
    reference.absolute(row) = std::abs(reference.exact(row));
  }
  expect_moments_near(planar_polygon_moments(lifted, degree), reference, tolerance);
  // A surface integral: the reversed polygon has the same moments.
  expect_moments_near(planar_polygon_moments(lifted.colwise().reverse(), degree), reference, tolerance);
}

TEST(PlanarPolygonMoments, RotatedPolygonMatchesQuadratureOnThe2dPolygon) {
  const Eigen::Vector2d centre(0.2, 0.3);
  const Eigen::MatrixXd polygon = star(centre);
  const Eigen::Matrix3d rotation = test::generic_rotation();
  const Eigen::Vector3d translation(5.0, -3.0, 2.0);
  Eigen::MatrixXd placed(polygon.rows(), 3);
  for (Eigen::Index i = 0; i < polygon.rows(); ++i) {
    placed.row(i) = embedded(polygon.row(i).transpose(), rotation, translation).transpose();
  }
  const auto place = [&](const Eigen::VectorXd& x) -> Eigen::VectorXd { return embedded(x, rotation, translation); };
  expect_moments_near(planar_polygon_moments(placed, degree),
                      test::fan_quadrature_moments(polygon, centre, degree, place, monomial_count(degree)), tolerance);
  // About a DG-style centre and scale: ((x − c)/s)^α.
  const Eigen::Vector3d basis_centre = translation + Eigen::Vector3d(0.1, 0.0, -0.2);
  const double scale = 0.8;
  const auto place_in_basis = [&](const Eigen::VectorXd& x) -> Eigen::VectorXd {
    return (embedded(x, rotation, translation) - basis_centre) / scale;
  };
  expect_moments_near(planar_polygon_moments(placed, degree, basis_centre, scale),
                      test::fan_quadrature_moments(polygon, centre, degree, place_in_basis, monomial_count(degree)),
                      tolerance);
}

TEST(PlanarPolygonMoments, AreaVectorOfNonConvexPolygon) {
  Eigen::MatrixXd l_shape(6, 3);
  l_shape << 0, 0, 1, 2, 0, 1, 2, 1, 1, 1, 1, 1, 1, 3, 1, 0, 3, 1;
  EXPECT_LE((polygon_area_vector(l_shape) - Eigen::Vector3d(0, 0, 4)).norm(), 1e-15);
  EXPECT_NEAR(planar_polygon_moments(l_shape, 0)(0), 4.0, 1e-15);
}

TEST(PolygonMoments, RejectsBadInput) {
  const Eigen::MatrixXd two_vertices = Eigen::MatrixXd::Ones(2, 2);
  EXPECT_THROW(polygon_moments_2d(two_vertices, 2), std::invalid_argument);
  const Eigen::MatrixXd triangle = (Eigen::MatrixXd(3, 2) << 0, 0, 1, 0, 0, 1).finished();
  EXPECT_THROW(polygon_moments_2d(triangle, -1), std::invalid_argument);
  EXPECT_THROW(polygon_moments_2d(triangle, 2, Eigen::Vector2d::Zero(), -1.0), std::invalid_argument);
  EXPECT_THROW(planar_polygon_moments(triangle, 2), std::invalid_argument);  // 2 columns, not 3
  Eigen::MatrixXd not_finite = Eigen::MatrixXd::Identity(3, 3);
  not_finite(1, 1) = std::numeric_limits<double>::infinity();
  EXPECT_THROW(planar_polygon_moments(not_finite, 2), std::invalid_argument);
}

}  // namespace
}  // namespace altfem
