// Motions u(X, t) and region selectors evaluated at sample points.
#include <gtest/gtest.h>

#include <numbers>

#include "shared/scene/scene.hpp"

namespace altfem {
namespace {

Scene with_condition(const std::string& condition) {
  return parse_scene(R"({"geometry": {"shape": {"box": {"min": [0, 0, 0], "max": [1, 1, 1]}}},
                         "material": {"youngs_modulus": 1, "poisson_ratio": 0},
                         "boundary_conditions": [)" +
                         condition + "]}",
                     "motion.json");
}

TEST(SceneMotion, RotateTurnsByOmegaTimesTAboutTheAxis) {
  const Motion motion =
      with_condition(R"({"type": "dirichlet", "region": {"sphere": {"centre": [0, 0, 0], "radius": 1}},
      "motion": {"kind": "rotate", "axis": [0, 0, 2], "centre": [1, 1, 0], "angular_velocity": 0.5}})")
          .dirichlet[0]
          .motion;
  // A quarter turn about (1, 1, z) at t = π: (2, 1, 5) → (1, 2, 5).
  const Eigen::Vector3d u = motion.displacement({2, 1, 5}, std::numbers::pi);
  EXPECT_NEAR((u - Eigen::Vector3d(-1, 1, 0)).norm(), 0.0, 1e-14);
  EXPECT_NEAR(motion.displacement({1, 1, 7}, 3.0).norm(), 0.0, 1e-15);  // on the axis
  EXPECT_NEAR(motion.displacement({2, 1, 5}, 0.0).norm(), 0.0, 1e-15);
}

TEST(SceneMotion, TranslateWithVelocity) {
  const Motion motion =
      with_condition(R"({"type": "dirichlet", "region": {"sphere": {"centre": [0, 0, 0], "radius": 1}},
      "motion": {"kind": "translate", "velocity": [1, -2, 0.5]}})")
          .dirichlet[0]
          .motion;
  EXPECT_EQ(motion.displacement({3, 3, 3}, 2.0), Eigen::Vector3d(2, -4, 1));
}

TEST(SceneMotion, TranslateDisplacementOverDurationThenHolds) {
  const Motion motion =
      with_condition(R"({"type": "dirichlet", "region": {"sphere": {"centre": [0, 0, 0], "radius": 1}},
      "motion": {"kind": "translate", "displacement": [0, 0, -0.2], "duration": 2}})")
          .dirichlet[0]
          .motion;
  EXPECT_NEAR(motion.displacement({0, 0, 0}, 0.5).z(), -0.05, 1e-15);
  EXPECT_NEAR(motion.displacement({0, 0, 0}, 2.0).z(), -0.2, 1e-15);
  EXPECT_NEAR(motion.displacement({0, 0, 0}, 7.0).z(), -0.2, 1e-15);
  EXPECT_EQ(motion.displacement({0, 0, 0}, 0.0), Eigen::Vector3d::Zero());
}

TEST(SceneMotion, FixedIsZeroAndComponentsDefaultToAll) {
  const DirichletCondition condition =
      with_condition(R"({"type": "dirichlet", "region": {"box": {"min": [0, 0, 0], "max": [1, 1, 0]}}})").dirichlet[0];
  EXPECT_EQ(condition.motion.kind, MotionKind::fixed);
  EXPECT_EQ(condition.motion.displacement({1, 2, 3}, 5.0), Eigen::Vector3d::Zero());
  EXPECT_EQ(condition.components, (std::array<bool, 3>{true, true, true}));
  EXPECT_EQ(condition.pointer, "/boundary_conditions/0");
}

TEST(SceneRegions, BoxWithToleranceSelectsItsFaces) {
  const RegionSelector region =
      with_condition(R"({"type": "dirichlet", "region": {"box": {"min": [-1, -1, -1], "max": [0, 1, 1]}}})")
          .dirichlet[0]
          .region;
  EXPECT_TRUE(region.contains({0, 0.5, 0.5}, 0.0));
  EXPECT_TRUE(region.contains({1e-10, 0.5, 0.5}, 1e-9));
  EXPECT_FALSE(region.contains({1e-8, 0.5, 0.5}, 1e-9));
  EXPECT_FALSE(region.contains({-0.5, 1.5, 0.5}, 1e-9));
  EXPECT_EQ(region.pointer, "/boundary_conditions/0/region");
}

TEST(SceneRegions, HalfSpaceSelectsTheSideTheNormalPointsAwayFrom) {
  const RegionSelector region =
      with_condition(R"({"type": "dirichlet", "region": {"half_space": {"point": [0, 0.5, 0], "normal": [0, 3, 0]}}})")
          .dirichlet[0]
          .region;
  EXPECT_TRUE(region.contains({7, 0.2, -4}, 0.0));
  EXPECT_TRUE(region.contains({0, 0.5, 0}, 0.0));
  EXPECT_FALSE(region.contains({0, 0.6, 0}, 0.0));
  EXPECT_TRUE(region.contains({0, 0.6, 0}, 0.2));  // the normal is unit: tolerance is a distance
  EXPECT_TRUE(std::isinf(region.bounds().max().x()));
}

TEST(SceneRegions, Sphere) {
  const RegionSelector region =
      with_condition(R"({"type": "dirichlet", "region": {"sphere": {"centre": [1, 1, 1], "radius": 0.5}},
                         "components": ["z", "x"]})")
          .dirichlet[0]
          .region;
  EXPECT_TRUE(region.contains({1, 1, 1.5}, 0.0));
  EXPECT_FALSE(region.contains({1, 1, 1.6}, 0.0));
  EXPECT_TRUE(
      region.bounds().isApprox(Eigen::AlignedBox3d(Eigen::Vector3d(0.5, 0.5, 0.5), Eigen::Vector3d(1.5, 1.5, 1.5))));
}

}  // namespace
}  // namespace altfem
