// Defaults of docs/scene-schema.md are filled into Scene::resolved and the structs.
#include <gtest/gtest.h>

#include "shared/scene/scene.hpp"

namespace altfem {
namespace {

const char* minimal = R"({
  "geometry": { "shape": { "box": { "min": [0, 0, 0], "max": [2, 2, 2] } } },
  "material": { "youngs_modulus": 1e6, "poisson_ratio": 0.25 }
})";

TEST(SceneDefaults, MinimalSceneIsResolvedCompletely) {
  const Scene scene = parse_scene(minimal, "some/folder/minimal.json");
  const nlohmann::json& resolved = scene.resolved;
  EXPECT_EQ(resolved["name"], "minimal");
  EXPECT_EQ(resolved["material"]["model"], "stable_neo_hookean");
  EXPECT_EQ(resolved["material"]["density"], 1000.0);
  EXPECT_EQ(resolved["geometry"]["scale"], 1.0);
  EXPECT_EQ(resolved["geometry"]["translate"], nlohmann::json::array({0.0, 0.0, 0.0}));
  EXPECT_EQ(resolved["boundary_conditions"], nlohmann::json::array());
  EXPECT_EQ(resolved["loads"]["gravity"], nlohmann::json::array({0.0, 0.0, 0.0}));
  EXPECT_EQ(resolved["initial_conditions"]["centre"], "centre_of_mass");
  EXPECT_EQ(resolved["time"], nlohmann::json({{"static", true}, {"load_steps", 1}}));
  EXPECT_EQ(resolved["events"], nlohmann::json::array());
  EXPECT_EQ(resolved["solver"]["nonlinear"], "newton");
  EXPECT_EQ(resolved["solver"]["tolerance"], 1e-5);
  EXPECT_EQ(resolved["solver"]["max_iterations"], 50);
  EXPECT_EQ(resolved["solver"]["line_search"], true);
  EXPECT_EQ(resolved["solver"]["project_spd"], false);
  EXPECT_EQ(resolved["solver"]["linear"], "cholmod");
  EXPECT_EQ(resolved["solver"]["preconditioner"], "jacobi");
  EXPECT_EQ(resolved["solver"]["linear_tolerance"], 1e-10);
  EXPECT_EQ(resolved["solver"]["linear_max_iterations"], 10000);
  EXPECT_EQ(resolved["output"], nlohmann::json({{"every", 1}, {"surface", true}, {"volume", true}}));
  // Method blocks are resolved by their methods (tests/unit/fem/test_fem_scene_block.cpp).
  EXPECT_EQ(resolved["discretization"], nlohmann::json::object());

  EXPECT_EQ(scene.name, "minimal");
  EXPECT_EQ(scene.material.density, 1000.0);
  EXPECT_TRUE(scene.time.is_static);
  EXPECT_FALSE(scene.initial.centre.has_value());
}

TEST(SceneDefaults, DynamicTimeAndRelativePaths) {
  const Scene scene = parse_scene(R"({
    "geometry": { "surface": "../models/thing.OBJ", "scale": 2, "translate": [1, 2, 3] },
    "material": { "youngs_modulus": 1e6, "poisson_ratio": 0.25 },
    "initial_conditions": { "centre": [1, 0, 0], "angular_velocity": [0, 0, 2] },
    "time": { "dt": 0.5, "steps": 4 }
  })",
                                  "/tmp/scenes/dynamic.json");
  EXPECT_EQ(scene.geometry.file, std::filesystem::path("/tmp/models/thing.OBJ"));
  EXPECT_EQ(scene.resolved["geometry"]["surface"], "/tmp/models/thing.OBJ");
  EXPECT_EQ(scene.geometry.scale, 2.0);
  EXPECT_EQ(scene.geometry.translate, Eigen::Vector3d(1, 2, 3));
  EXPECT_FALSE(scene.time.is_static);
  EXPECT_EQ(scene.time.dt, 0.5);
  EXPECT_EQ(scene.time.steps, 4);
  EXPECT_EQ(scene.time.integrator, IntegratorKind::backward_euler);
  EXPECT_EQ(scene.resolved["time"]["rayleigh_damping"], nlohmann::json({{"mass", 0.0}, {"stiffness", 0.0}}));
  // v + ω × (x − c): ω = 2 ẑ, x − c = ŷ ⇒ −2 x̂.
  EXPECT_EQ(scene.initial.velocity_at({1, 1, 0}, {9, 9, 9}), Eigen::Vector3d(-2, 0, 0));
}

TEST(SceneDefaults, ResolvedSceneParsesToTheSameScene) {
  const Scene scene = parse_scene(minimal, "minimal.json");
  const Scene again = parse_scene(scene.resolved.dump(), "minimal.json");
  EXPECT_EQ(again.resolved, scene.resolved);
}

}  // namespace
}  // namespace altfem

namespace altfem {
namespace {

// A refine event's defaults, and `every` as one refinement per n steps until the run ends
// (dynamic: before the last step; static: after the last load step but one).
TEST(SceneDefaults, ARefineEventRepeatsEveryNStepsUntilTheRunEnds) {
  const std::string bar = R"({
    "geometry": { "shape": { "box": { "min": [0, 0, 0], "max": [1, 0.1, 0.1] } } },
    "material": { "youngs_modulus": 1e6, "poisson_ratio": 0.25 },
    "time": TIME,
    "events": [ { "time": START, "refine": { "threshold": 1e3, "every": EVERY } } ] })";
  const auto times_of = [&](const std::string& time, const std::string& start, const std::string& every) {
    std::string text = bar;
    text.replace(text.find("TIME"), 4, time);
    text.replace(text.find("START"), 5, start);
    text.replace(text.find("EVERY"), 5, every);
    std::vector<double> times;
    for (const SceneEvent& event : parse_scene(text, "bar.json").events) {
      EXPECT_EQ(event.kind, EventKind::refine);
      EXPECT_EQ(event.refine.split, RefineSplit::eighths);
      EXPECT_EQ(event.refine.max_level, 3);
      EXPECT_EQ(event.refine.threshold, 1e3);
      EXPECT_FALSE(event.refine.region);
      times.push_back(event.time);
    }
    return times;
  };
  const std::vector<double> dynamic = times_of(R"({ "dt": 0.01, "steps": 20 })", "0.05", "5");
  ASSERT_EQ(dynamic.size(), 3u);  // 0.05, 0.10, 0.15: 0.20 is the run's end
  EXPECT_NEAR(dynamic[2], 0.15, 1e-15);
  EXPECT_EQ(times_of(R"({ "static": true, "load_steps": 4 })", "1", "1"), (std::vector<double>{1, 2, 3}));
}

}  // namespace
}  // namespace altfem
