// The graded monomial order every moment routine uses, and the binomial change of
// centre and scale that turns moments in a body's own frame into the caller's.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <stdexcept>

#include "shared/geometry/monomial_index.hpp"
#include "shared/geometry/monomial_shift.hpp"
#include "tests/unit/geometry/moments_reference.hpp"

namespace altfem {
namespace {

TEST(MonomialIndex, ExponentTableFollowsTheDocumentedOrder) {
  const auto exponents = monomial_exponents(12);
  ASSERT_EQ(exponents.rows(), monomial_count(12));
  EXPECT_EQ(monomial_count(12), 455);
  EXPECT_EQ(monomial_count(0), 1);
  EXPECT_EQ(monomial_count(-1), 0);
  for (Eigen::Index row = 0; row < exponents.rows(); ++row) {
    EXPECT_EQ(monomial_index(exponents(row, 0), exponents(row, 1), exponents(row, 2)), row);
    EXPECT_EQ(monomial_index(Eigen::Matrix<int, 1, 3>(exponents.row(row))), row);
  }
  // 1, x, y, z, x², xy, xz, y², yz, z²
  const Eigen::Matrix<int, 10, 3> first_ten = (Eigen::Matrix<int, 10, 3>() << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 2, 0,
                                               0, 1, 1, 0, 1, 0, 1, 0, 2, 0, 0, 1, 1, 0, 0, 2)
                                                  .finished();
  EXPECT_TRUE((exponents.topRows(10) == first_ten)) << exponents.topRows(10);
  EXPECT_THROW(monomial_exponents(-1), std::invalid_argument);
}

TEST(MonomialIndex, TwoDimensionalOrder) {
  const auto exponents = monomial_exponents_2d(9);
  ASSERT_EQ(exponents.rows(), monomial_count_2d(9));
  for (Eigen::Index row = 0; row < exponents.rows(); ++row) {
    EXPECT_EQ(monomial_index_2d(exponents(row, 0), exponents(row, 1)), row);
    EXPECT_GE(exponents.row(row).sum(), exponents.row(row > 0 ? row - 1 : 0).sum());
  }
  EXPECT_EQ(monomial_index_2d(1, 0), 1);
  EXPECT_EQ(monomial_index_2d(0, 1), 2);
}

// Box moments about the box's centre, shifted, equal the analytic moments about a far
// centre (the raw moments) and about another centre and scale near the box. (The other
// direction, from a far frame to a near one, cancels catastrophically: shift_moments.hpp.)
TEST(ShiftMoments, ChangesCentreAndScaleExactly) {
  const int degree = 9;
  const Eigen::Vector3d low(-0.5, 0.25, 1.0), high(1.5, 0.75, 1.5), centre = 0.5 * (low + high);
  const double scale = 1.0;
  const Eigen::VectorXd centred = test::box_moments(low - centre, high - centre, degree).exact;
  test::expect_moments_near(shift_moments(centred, degree, centre / scale, 1.0 / scale),
                            test::box_moments(low, high, degree), 1e-13);
  const Eigen::Vector3d near_centre(0.4, 0.3, 1.2);
  const double near_scale = 0.7;
  // ((x − c')/s')^α = ((c − c')/s' + (1/s')·(x − c))^α, in the physical volume measure.
  const Eigen::VectorXd shifted = shift_moments(centred, degree, (centre - near_centre) / near_scale, 1.0 / near_scale);
  test::ReferenceMoments expected =
      test::box_moments((low - near_centre) / near_scale, (high - near_centre) / near_scale, degree);
  expected.exact *= near_scale * near_scale * near_scale;
  expected.absolute *= near_scale * near_scale * near_scale;
  test::expect_moments_near(shifted, expected, 1e-13);
  EXPECT_THROW(shift_moments(centred.head(5), degree, centre, 1.0), std::invalid_argument);
}

TEST(ShiftMoments, TwoDimensionalRoundTrip) {
  const int degree = 8;
  const test::ReferenceMoments raw = test::rectangle_moments({0.1, -0.3}, {0.9, 0.4}, degree);
  const Eigen::Vector2d offset(0.3, -0.2);
  const Eigen::VectorXd there = shift_moments_2d(raw.exact, degree, offset, 1.5);
  const Eigen::VectorXd back = shift_moments_2d(there, degree, -offset / 1.5, 1.0 / 1.5);
  test::expect_moments_near(back, raw, 1e-13);
}

TEST(MomentFrame, BoundingBoxCentreAndHalfLongestSide) {
  Eigen::MatrixXd points(3, 3);
  points << 1, 2, 3, 5, 2, 4, 3, 1, 3.5;
  const MomentFrame frame = bounding_box_frame(points);
  EXPECT_LE((frame.centre - Eigen::Vector3d(3, 1.5, 3.5)).norm(), 1e-15);
  EXPECT_DOUBLE_EQ(frame.scale, 2.0);
  EXPECT_THROW(bounding_box_frame(Eigen::MatrixXd::Ones(4, 3)), std::invalid_argument);
}

}  // namespace
}  // namespace altfem
