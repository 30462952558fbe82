// Analytic shapes: level-set signs and exact distances, bounding boxes, exact
// volumes, CSG inside tests, and the octree volume against exact answers.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "shared/common/error.hpp"
#include "shared/geometry/analytic_shape.hpp"

namespace altfem {
namespace {

using Eigen::Vector3d;
constexpr double pi = std::numbers::pi;

bool same_box(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b, double tolerance = 1e-14) {
  return (a.min() - b.min()).norm() <= tolerance && (a.max() - b.max()).norm() <= tolerance;
}

TEST(AnalyticShape, BoxIsAnExactSignedDistance) {
  const auto box = make_box({0, 0, 0}, {2, 1, 1});
  EXPECT_DOUBLE_EQ(box->level_set({1, 0.5, 0.5}), -0.5);
  EXPECT_DOUBLE_EQ(box->level_set({1, 0.5, 0.9}), -0.1);
  EXPECT_DOUBLE_EQ(box->level_set({3, 0.5, 0.5}), 1.0);
  EXPECT_DOUBLE_EQ(box->level_set({3, 2, 0.5}), std::sqrt(2.0));  // nearest point is an edge
  EXPECT_DOUBLE_EQ(box->level_set({2, 1, 1}), 0.0);
  EXPECT_TRUE(box->contains({2, 1, 1}));
  EXPECT_FALSE(box->contains({2.001, 0.5, 0.5}));
  EXPECT_DOUBLE_EQ(box->volume(), 2.0);
  EXPECT_TRUE(same_box(box->bounding_box(), {Vector3d(0, 0, 0), Vector3d(2, 1, 1)}));
  EXPECT_TRUE(box->is_convex());
}

TEST(AnalyticShape, Sphere) {
  const auto sphere = make_sphere({1, 0, 0}, 2);
  EXPECT_DOUBLE_EQ(sphere->level_set({1, 0, 0}), -2.0);
  EXPECT_DOUBLE_EQ(sphere->level_set({1, 0, 5}), 3.0);
  EXPECT_DOUBLE_EQ(sphere->volume(), 32.0 / 3.0 * pi);
  EXPECT_TRUE(same_box(sphere->bounding_box(), {Vector3d(-1, -2, -2), Vector3d(3, 2, 2)}));
}

TEST(AnalyticShape, SolidCylinderAlongATiltedAxis) {
  const Vector3d axis = Vector3d(1, 1, 0).normalized();
  const auto cylinder = make_cylinder({0, 0, 0}, Vector3d(3, 3, 0), 2.0, 0.5);
  const Vector3d across = Vector3d(1, -1, 0).normalized();
  EXPECT_DOUBLE_EQ(cylinder->level_set(1.0 * axis), -0.5);  // on the axis, mid-height
  EXPECT_NEAR(cylinder->level_set(axis + 0.25 * across), -0.25, 1e-15);
  EXPECT_NEAR(cylinder->level_set(3.0 * axis), 1.0, 1e-15);                             // beyond the top cap
  EXPECT_NEAR(cylinder->level_set(-1.0 * axis + 1.5 * across), std::sqrt(2.0), 1e-15);  // off the rim
  EXPECT_DOUBLE_EQ(cylinder->volume(), pi * 0.25 * 2.0);
  const double reach = 0.5 * std::sqrt(0.5);  // R sqrt(1 − a_i²) for a = (1, 1, 0)/√2
  const Vector3d top = 2.0 * axis;
  EXPECT_TRUE(same_box(cylinder->bounding_box(),
                       {Vector3d(-reach, -reach, -0.5), Vector3d(top.x() + reach, top.y() + reach, 0.5)}));
}

TEST(AnalyticShape, HollowCylinder) {
  const auto tube = make_cylinder({0, 0, 1}, {0, 0, -1}, 1.0, 1.0, 0.5);  // from z = 1 down to 0
  EXPECT_FALSE(tube->contains({0, 0, 0.5}));                              // in the bore
  EXPECT_DOUBLE_EQ(tube->level_set({0, 0, 0.5}), 0.5);
  EXPECT_DOUBLE_EQ(tube->level_set({0.75, 0, 0.5}), -0.25);
  EXPECT_DOUBLE_EQ(tube->level_set({0.75, 0, 1.5}), 0.5);
  EXPECT_DOUBLE_EQ(tube->volume(), pi * (1.0 - 0.25));
  EXPECT_FALSE(tube->is_convex());
  EXPECT_TRUE(same_box(tube->bounding_box(), {Vector3d(-1, -1, 0), Vector3d(1, 1, 1)}));
}

TEST(AnalyticShape, InvalidParametersAreInputErrors) {
  EXPECT_THROW(make_box({0, 0, 0}, {1, 0, 1}), InputError);
  EXPECT_THROW(make_sphere({0, 0, 0}, 0.0), InputError);
  EXPECT_THROW(make_cylinder({0, 0, 0}, {0, 0, 0}, 1, 1), InputError);
  EXPECT_THROW(make_cylinder({0, 0, 0}, {0, 0, 1}, 1, 1, 1), InputError);
  EXPECT_THROW(make_union({make_sphere({0, 0, 0}, 1)}), InputError);
}

TEST(AnalyticShapeCsg, InsideTests) {
  const auto box = make_box({-1, -1, -1}, {1, 1, 1});
  const auto ball = make_sphere({1, 0, 0}, 0.5);
  const auto united = make_union({box, ball});
  const auto common = make_intersection({box, ball});
  const auto carved = make_difference({box, ball});
  const Vector3d in_box_only(0, 0, 0), in_both(0.9, 0, 0), in_ball_only(1.3, 0, 0), in_neither(0, 3, 0);
  EXPECT_TRUE(united->contains(in_box_only) && united->contains(in_both) && united->contains(in_ball_only));
  EXPECT_FALSE(united->contains(in_neither));
  EXPECT_TRUE(common->contains(in_both));
  EXPECT_FALSE(common->contains(in_box_only) || common->contains(in_ball_only));
  EXPECT_TRUE(carved->contains(in_box_only));
  EXPECT_FALSE(carved->contains(in_both) || carved->contains(in_ball_only));
  EXPECT_TRUE(same_box(united->bounding_box(), {Vector3d(-1, -1, -1), Vector3d(1.5, 1, 1)}));
  EXPECT_TRUE(same_box(common->bounding_box(), {Vector3d(0.5, -0.5, -0.5), Vector3d(1, 0.5, 0.5)}));
  EXPECT_TRUE(same_box(carved->bounding_box(), box->bounding_box()));
}

TEST(AnalyticShapeCsg, ExactVolumesOfDisjointAndNestedShapes) {
  const auto box = make_box({-1, -1, -1}, {1, 1, 1});
  const auto inner = make_sphere({0, 0, 0}, 0.5);
  const auto far = make_sphere({5, 0, 0}, 1);
  EXPECT_DOUBLE_EQ(*make_difference({box, inner})->exact_volume(), 8.0 - pi / 6.0);
  EXPECT_DOUBLE_EQ(*make_union({box, far})->exact_volume(), 8.0 + 4.0 / 3.0 * pi);
  EXPECT_DOUBLE_EQ(*make_union({box, inner})->exact_volume(), 8.0);
  EXPECT_DOUBLE_EQ(*make_intersection({box, inner})->exact_volume(), pi / 6.0);
  EXPECT_DOUBLE_EQ(*make_intersection({box, far})->exact_volume(), 0.0);
  EXPECT_DOUBLE_EQ(*make_difference({box, far})->exact_volume(), 8.0);
  EXPECT_FALSE(make_union({box, make_sphere({1, 0, 0}, 0.5)})->exact_volume().has_value());
}

TEST(AnalyticShapeCsg, OctreeVolumeMatchesExactAnswers) {
  // Half a ball sticking out of a box face: the union adds half the ball.
  const auto box = make_box({-1, -1, -1}, {1, 1, 1});
  const auto half_out = make_union({box, make_sphere({1, 0, 0}, 0.5)});
  EXPECT_FALSE(half_out->exact_volume().has_value());
  EXPECT_NEAR(half_out->volume(), 8.0 + pi / 12.0, 1e-4 * 8.0);
  // A ball cut by a slab: a spherical cap.
  const auto cap = make_intersection({make_sphere({0, 0, 0}, 1), make_box({-2, -2, 0.5}, {2, 2, 2})});
  const double h = 0.5;  // spherical cap of height h: π h² (3R − h) / 3
  EXPECT_NEAR(cap->volume(), pi * h * h * (3.0 - h) / 3.0, 1e-4 * pi * h * h * (3.0 - h) / 3.0);
  // The octree also reproduces primitives.
  EXPECT_NEAR(integrate_volume(*make_cylinder({0, 0, 0}, {1, 2, 3}, 2, 0.3, 0.1), 1e-4), pi * 0.08 * 2,
              1e-4 * pi * 0.08 * 2);
}

TEST(AnalyticShape, ScaledTranslated) {
  const auto moved = make_scaled_translated(make_sphere({1, 0, 0}, 1), 2.0, {0, 0, 3});
  EXPECT_DOUBLE_EQ(moved->level_set({2, 0, 3}), -2.0);
  EXPECT_DOUBLE_EQ(moved->level_set({2, 0, 8}), 3.0);
  EXPECT_DOUBLE_EQ(moved->volume(), 32.0 / 3.0 * pi);
  EXPECT_TRUE(same_box(moved->bounding_box(), {Vector3d(0, -2, 1), Vector3d(4, 2, 5)}));
}

}  // namespace
}  // namespace altfem
