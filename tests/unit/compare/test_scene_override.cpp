// --set KEY=VALUE: parsing, assignment into the document, and errors that name the assignment.
#include <gtest/gtest.h>

#include "shared/common/error.hpp"
#include "shared/fem/fem_scene_block.hpp"
#include "shared/scene/scene_override.hpp"

namespace altfem {
namespace {

using nlohmann::json;

const char* beam = R"({"geometry": {"shape": {"box": {"min": [0,0,0], "max": [1,0.1,0.1]}}},
  "material": {"youngs_modulus": 1e6, "poisson_ratio": 0.3}})";

TEST(SceneOverride, ParsesJsonValuesAndFallsBackToStrings) {
  EXPECT_EQ(parse_scene_override("discretization/fem/resolution=[8,2,2]").value, json::array({8, 2, 2}));
  EXPECT_EQ(parse_scene_override("/material/poisson_ratio=0.45").value, json(0.45));
  EXPECT_EQ(parse_scene_override("a=true").value, json(true));
  EXPECT_EQ(parse_scene_override("a=\"tet4\"").value, json("tet4"));
  EXPECT_EQ(parse_scene_override("a=tet4").value, json("tet4"));
  EXPECT_EQ(parse_scene_override("a=[1,2").value, json("[1,2"));  // not JSON: a string, rejected by validation
  EXPECT_EQ(parse_scene_override("a/b=1").pointer, "/a/b");
}

TEST(SceneOverride, RejectsMissingEqualsAndEmptyKeys) {
  EXPECT_THROW(parse_scene_override("discretization/fem/resolution"), InputError);
  EXPECT_THROW(parse_scene_override("=3"), InputError);
  EXPECT_THROW(parse_scene_override("/=3"), InputError);
  EXPECT_THROW(parse_scene_override("a~2=3"), InputError);  // '~' must be ~0 or ~1
}

TEST(SceneOverride, AssignsCreatesObjectsAndIndexesArrays) {
  json document = json::parse(R"({"a": {"b": 1}, "list": [10, 20]})");
  apply_scene_overrides(document,
                        {parse_scene_override("a/b=2"), parse_scene_override("x/y/z=3"),
                         parse_scene_override("list/1=21"), parse_scene_override("list/-=30")},
                        "scene.json");
  EXPECT_EQ(document, json::parse(R"({"a": {"b": 2}, "x": {"y": {"z": 3}}, "list": [10, 21, 30]})"));
}

TEST(SceneOverride, ErrorsNameTheAssignment) {
  json document = json::parse(R"({"a": "text", "list": [1]})");
  try {
    apply_scene_overrides(document, {parse_scene_override("a/b=1")}, "scene.json");
    FAIL();
  } catch (const InputError& error) {
    EXPECT_STREQ(error.what(), "scene.json: --set a/b=1: /a is a string, not an object or array");
  }
  EXPECT_THROW(apply_scene_overrides(document, {parse_scene_override("list/5=1")}, "s"), InputError);
  EXPECT_THROW(apply_scene_overrides(document, {parse_scene_override("list/x=1")}, "s"), InputError);
}

TEST(SceneOverride, OverridesAreValidatedLikeTheScene) {
  const Scene scene = parse_scene(beam, "beam.json",
                                  {parse_scene_override("discretization/fem/resolution=[8,2,2]"),
                                   parse_scene_override("discretization/fem/element=tet4")});
  EXPECT_EQ(fem_spec(scene).resolution, Eigen::Vector3i(8, 2, 2));
  EXPECT_EQ(fem_spec(scene).element, ElementType::tet4);
  try {
    (void)parse_scene(beam, "beam.json", {parse_scene_override("material/poisson_ratio=0.5")});
    FAIL();
  } catch (const InputError& error) {
    EXPECT_STREQ(error.what(), "beam.json: /material/poisson_ratio: must be < 0.5, got 0.5");
  }
}

}  // namespace
}  // namespace altfem
