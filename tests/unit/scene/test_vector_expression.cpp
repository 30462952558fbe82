// VectorExpression: values, constants, time dependence, non-finite values, and
// evaluation from several threads at once (each borrows its own muParser parser).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <thread>
#include <vector>

#include "shared/common/error.hpp"
#include "shared/scene/scene.hpp"

namespace altfem {
namespace {

TEST(VectorExpression, EvaluatesWithConstantsPiAndTime) {
  const VectorExpression f({"a*sin(pi*x)", "y^2 + t", "2"}, {{"a", 3.0}}, "scene.json", "/loads/body_force");
  const Eigen::Vector3d value = f({0.25, 2.0, 7.0}, 0.5);
  EXPECT_DOUBLE_EQ(value.x(), 3.0 * std::sin(std::numbers::pi * 0.25));
  EXPECT_DOUBLE_EQ(value.y(), 4.5);
  EXPECT_DOUBLE_EQ(value.z(), 2.0);
  EXPECT_TRUE(f.depends_on_time());
  EXPECT_FALSE(VectorExpression({"x", "y", "z"}, {}, "s", "/p").depends_on_time());
}

TEST(VectorExpression, NonFiniteValueIsANumericalErrorNamingTheKey) {
  const VectorExpression f({"1/x", "0", "0"}, {}, "scene.json", "/exact_displacement");
  try {
    f({0.0, 0.0, 0.0}, 0.0);
    FAIL() << "expected a NumericalError";
  } catch (const NumericalError& error) {
    EXPECT_NE(std::string(error.what()).find("/exact_displacement: the expression is not finite"), std::string::npos)
        << error.what();
  }
}

TEST(VectorExpression, ThreadsEvaluatingAtOnceGetTheSerialValues) {
  const VectorExpression f({"sin(x)*cos(y) + z", "exp(-x*y)", "x*y*z - t"}, {}, "s", "/p");
  Eigen::MatrixXd points = Eigen::MatrixXd::Random(4000, 3);
  const Eigen::MatrixXd serial = f.evaluate(points, 0.3);
  constexpr int thread_count = 4;
  std::vector<Eigen::MatrixXd> results(thread_count);
  std::vector<std::thread> threads;
  for (int i = 0; i < thread_count; ++i)
    threads.emplace_back([&, i] {
      // Alternate batch and point-wise evaluation so that the pool is shared heavily.
      results[i].resize(points.rows(), 3);
      for (Eigen::Index p = 0; p < points.rows(); ++p) {
        if (p % 2 == 0) results[i].row(p) = f(points.row(p).transpose(), 0.3).transpose();
        else results[i].row(p) = f.evaluate(points.row(p), 0.3).row(0);
      }
    });
  for (auto& thread : threads) thread.join();
  for (const auto& result : results) EXPECT_EQ(result, serial);
}

TEST(VectorExpression, FieldMotionPrescribesTheExpression) {
  const Scene scene = parse_scene(R"({"geometry": {"shape": {"box": {"min": [0,0,0], "max": [1,1,1]}}},
    "material": {"youngs_modulus": 1e6, "poisson_ratio": 0.3}, "constants": {"c": 0.5},
    "boundary_conditions": [{"type": "dirichlet", "region": {"box": {"min": [0,0,0], "max": [0,1,1]}},
                             "motion": {"kind": "field", "displacement": ["c*t*y", 0, "z"]}}],
    "loads": {"body_force": ["0", "0", "-9.81*1000"]}, "exact_displacement": ["x", "y", "z"]})",
                                  "scene.json");
  const Motion& motion = scene.dirichlet[0].motion;
  EXPECT_EQ(motion.kind, MotionKind::field);
  EXPECT_EQ(motion.displacement({0.0, 2.0, 3.0}, 4.0), Eigen::Vector3d(4.0, 0.0, 3.0));
  ASSERT_TRUE(scene.body_force.has_value());
  EXPECT_EQ(scene.body_force({0, 0, 0}, 0), Eigen::Vector3d(0, 0, -9810));
  EXPECT_TRUE(scene.exact_displacement.has_value());
  EXPECT_EQ(scene.resolved["constants"]["c"], 0.5);
}

// A traction may use the outward normal; a body force may not (nx is unknown there).
TEST(VectorExpression, OnlySurfaceExpressionsKnowTheNormal) {
  const std::string head = R"({"geometry": {"shape": {"box": {"min": [0,0,0], "max": [1,1,1]}}},
    "material": {"youngs_modulus": 1e6, "poisson_ratio": 0.3}, "loads": )";
  const Scene scene = parse_scene(
      head + R"({"traction": [{"region": {"box": {"min": [1,0,0], "max": [1,1,1]}}, "traction": ["2*nx", "y", 0]}]}})",
      "scene.json");
  ASSERT_TRUE(scene.tractions[0].traction_field.has_value());
  EXPECT_FALSE(scene.tractions[0].traction.has_value());
  const Eigen::MatrixXd value =
      scene.tractions[0].traction_field.evaluate(Eigen::RowVector3d(1, 0.5, 0), Eigen::RowVector3d(1, 0, 0), 0.0);
  EXPECT_EQ(value, Eigen::RowVector3d(2, 0.5, 0));
  try {
    parse_scene(head + R"({"body_force": ["nx", 0, 0]}})", "scene.json");
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("scene.json: /loads/body_force/0: cannot parse"), std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace altfem
