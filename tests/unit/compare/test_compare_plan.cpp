// Configuration expansion: methods × the product of sweeps, per-method keys, the reference.
#include <gtest/gtest.h>

#include "shared/common/error.hpp"
#include "shared/compare/compare_plan.hpp"

namespace altfem {
namespace {

using nlohmann::json;

TEST(ComparePlan, SplitsOnlyAtTopLevelCommas) {
  EXPECT_EQ(split_top_level("[1,2],[3,4],x", ','), (std::vector<std::string>{"[1,2]", "[3,4]", "x"}));
  EXPECT_EQ(split_top_level(R"("a,b",{"c":[1,2]})", ','), (std::vector<std::string>{R"("a,b")", R"({"c":[1,2]})"}));
}

TEST(ComparePlan, ParsesSweepsAndReference) {
  const Sweep sweep = parse_sweep("discretization/fem/resolution=[10,1,1],[20,2,2]");
  EXPECT_EQ(sweep.pointer, "/discretization/fem/resolution");
  ASSERT_EQ(sweep.values.size(), 2u);
  EXPECT_EQ(sweep.values[1], json::array({20, 2, 2}));
  EXPECT_THROW(parse_sweep("discretization/fem/element=tet4,,hex8"), InputError);
  EXPECT_THROW(parse_sweep("novalues"), InputError);
  const ReferenceSpec reference =
      parse_reference("fem:discretization/fem/element=hex27,discretization/fem/resolution=[8,2,2]");
  EXPECT_EQ(reference.method, "fem");
  ASSERT_EQ(reference.overrides.size(), 2u);
  EXPECT_EQ(reference.overrides[1].value, json::array({8, 2, 2}));
  EXPECT_TRUE(parse_reference("fem").overrides.empty());
  EXPECT_THROW(parse_reference(":a=1"), InputError);
}

TEST(ComparePlan, ExpandsTheProductAndAppliesMethodKeysToTheirMethodOnly) {
  ComparePlan plan;
  plan.methods = {"fem", "dg"};
  plan.sweeps = {
      {parse_sweep("discretization/fem/element=tet4,hex8"), parse_sweep("material/poisson_ratio=0.3,0.4,0.45")}};
  plan.reference = parse_reference("fem:discretization/fem/element=hex27");
  const auto configurations = expand_configurations(plan);
  // fem: 2 × 3; dg: the scene-wide sweep only, 3; the reference last.
  ASSERT_EQ(configurations.size(), 6u + 3u + 1u);
  EXPECT_EQ(configurations[0].label(), "fem element=tet4 poisson_ratio=0.3");
  EXPECT_EQ(configurations[1].label(), "fem element=tet4 poisson_ratio=0.4");
  EXPECT_EQ(configurations[5].label(), "fem element=hex8 poisson_ratio=0.45");
  EXPECT_EQ(configurations[6].label(), "dg poisson_ratio=0.3");
  EXPECT_EQ(configurations[6].overrides.size(), 1u);
  EXPECT_FALSE(configurations[8].is_reference);
  EXPECT_TRUE(configurations[9].is_reference);
  EXPECT_EQ(configurations[9].overrides[0].text, "discretization/fem/element=hex27");
}

TEST(ComparePlan, ReadsTheSceneBlockAndDefaultsToEveryMethod) {
  const json block = json::parse(R"({"methods": ["fem"], "sweeps": {"discretization/fem/resolution": [[2,1,1],[4,1,1]]},
    "reference": {"method": "fem", "set": {"discretization/fem/element": "hex27"}}})");
  const ComparePlan plan = plan_from_scene(block, {"fem", "fcm"});
  EXPECT_EQ(plan.methods, std::vector<std::string>{"fem"});
  ASSERT_EQ(plan.sweeps.size(), 1u);
  ASSERT_EQ(plan.sweeps[0].size(), 1u);
  EXPECT_EQ(plan.sweeps[0][0].pointer, "/discretization/fem/resolution");
  ASSERT_TRUE(plan.reference);
  EXPECT_EQ(plan.reference->overrides[0].text, "discretization/fem/element=hex27");
  const ComparePlan defaults = plan_from_scene(json(), {"fem", "fcm"});
  EXPECT_EQ(defaults.methods, (std::vector<std::string>{"fem", "fcm"}));
  EXPECT_EQ(expand_configurations(defaults).size(), 2u);
  EXPECT_FALSE(defaults.reference);
}

// Sweeps as an array of groups run the union of the groups' products: uniform grids in
// one, refinement cycles from the coarse grid in the other — 2 + 1 runs, not 2 × 2. A
// configuration two groups both make (the third group's) is listed again; compare runs it
// once, by its resolved scene's hash.
TEST(ComparePlan, RunsTheUnionOfSweepGroups) {
  const json block = json::parse(R"({"methods": ["fem"], "sweeps": [
    {"discretization/fem/resolution": [[4,4,1], [8,8,2]]},
    {"discretization/fem/resolution": [[4,4,1]], "events": [[{"time": 0, "refine": {"cycles": 2}}]]},
    {"discretization/fem/resolution": [[8,8,2]]}]})");
  const auto configurations = expand_configurations(plan_from_scene(block, {"fem"}));
  ASSERT_EQ(configurations.size(), 4u);
  EXPECT_EQ(configurations[0].label(), "fem resolution=[4,4,1]");
  EXPECT_EQ(configurations[1].label(), "fem resolution=[8,8,2]");
  EXPECT_EQ(configurations[2].label(), "fem resolution=[4,4,1] events(cycles=2,time=0)");
  EXPECT_EQ(configurations[3].label(), "fem resolution=[8,8,2]");
}

// A long swept value is named by the leaves in which it differs from the sweep's other
// values: refinement events by their cycles, not their whole JSON.
TEST(ComparePlan, NamesLongSweptValuesByWhatTellsThemApart) {
  const json block = json::parse(R"({"methods": ["fem"], "sweeps": {"events": [
    [{"time": 0, "refine": {"criterion": "error_indicator", "fraction": 0.5, "cycles": 2}}],
    [{"time": 0, "refine": {"criterion": "error_indicator", "fraction": 0.5, "cycles": 4}}]]},
    "reference": {"method": "fem", "set": {"discretization/fem/element": "hex27"}}})");
  const auto configurations = expand_configurations(plan_from_scene(block, {"fem"}));
  ASSERT_EQ(configurations.size(), 3u);
  EXPECT_EQ(configurations[0].label(), "fem events(cycles=2)");
  EXPECT_EQ(configurations[1].label(), "fem events(cycles=4)");
  EXPECT_EQ(configurations[2].label(), "fem element=hex27");
}

}  // namespace
}  // namespace altfem
