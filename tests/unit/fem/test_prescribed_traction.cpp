// PrescribedTraction (issue #34): the traction the error indicator's boundary residual
// compares σn with — none where a Dirichlet condition holds the point, the surface loads
// (scaled by their ramps) where their regions hold it, 0 elsewhere.
#include <gtest/gtest.h>

#include "shared/scene/scene.hpp"
#include "shared/simulation/prescribed_traction.hpp"

namespace altfem {
namespace {

// A unit cube clamped at x = 0, pulled by 2 Pa along x at x = 1 (ramped over 4 s), pressed
// by 3 Pa on y = 1, on a roller at z = 0 (its traction's z is the reaction, unknown).
const char* const cube = R"({
  "geometry": { "shape": { "box": { "min": [0, 0, 0], "max": [1, 1, 1] } } },
  "material": { "model": "linear", "youngs_modulus": 1e6, "poisson_ratio": 0.3, "density": 1000 },
  "boundary_conditions": [
    { "type": "dirichlet", "name": "clamp", "region": { "box": { "min": [-1, -1, -1], "max": [0, 2, 2] } } },
    { "type": "dirichlet", "name": "roller", "components": ["z"], "region": { "box": { "min": [-1, -1, -1], "max": [2, 2, 0] } } }
  ],
  "loads": { "traction": [
    { "region": { "box": { "min": [1, -1, -1], "max": [2, 2, 2] } }, "traction": [2, 0, 0], "ramp": 4 },
    { "region": { "box": { "min": [-1, 1, -1], "max": [2, 2, 2] } }, "pressure": 3 } ] },
  "time": { "static": true }
})";

TEST(PrescribedTraction, HeldPointsHaveNoneLoadedOnesTheLoadsAndFreeOnesZero) {
  const Scene scene = parse_scene(cube, "cube.json");
  const PrescribedTraction boundary(scene, 1.0, 1e-9);
  EXPECT_FALSE(boundary.at({0, 0.5, 0.5}, -Eigen::Vector3d::UnitX()).has_value());               // clamped
  EXPECT_EQ(*boundary.at({1, 0.5, 0.5}, Eigen::Vector3d::UnitX()), Eigen::Vector3d(0.5, 0, 0));  // 2 Pa × 1/4
  EXPECT_EQ(*boundary.at({0.5, 1, 0.5}, Eigen::Vector3d::UnitY()), Eigen::Vector3d(0, -3, 0));   // −p n
  EXPECT_EQ(*boundary.at({1, 1, 0.5}, Eigen::Vector3d::UnitY()), Eigen::Vector3d(0.5, -3, 0));   // both loads
  EXPECT_FALSE(boundary.at({0.5, 0.5, 0}, -Eigen::Vector3d::UnitZ()).has_value());               // on the roller
  EXPECT_EQ(*boundary.at({0.5, 0, 0.5}, -Eigen::Vector3d::UnitY()), Eigen::Vector3d::Zero());    // free
}

TEST(PrescribedTraction, AReleasedConditionHoldsNothing) {
  const Scene scene = parse_scene(cube, "cube.json");
  const PrescribedTraction boundary(scene, 8.0, 1e-9, ConditionSet{1});  // the clamp released, not the roller
  EXPECT_EQ(*boundary.at({0, 0.5, 0.5}, -Eigen::Vector3d::UnitX()), Eigen::Vector3d::Zero());
  EXPECT_EQ(*boundary.at({1, 0.5, 0.5}, Eigen::Vector3d::UnitX()), Eigen::Vector3d(2, 0, 0));  // past the ramp
  EXPECT_FALSE(boundary.at({0.5, 0.5, 0}, -Eigen::Vector3d::UnitZ()).has_value());
}

}  // namespace
}  // namespace altfem
