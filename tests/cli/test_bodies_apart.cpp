// Bodies closer than a cell stay apart in every method: the two boxes 4 mm apart of
// tests/cli/scenes/two_boxes.json, one clamped, under gravity; the free box must fall
// freely (exact for backward Euler, checked by check_free_fall.py on the embedded surface).
// fcm's topology-aware cells (issue 17): the background cells and nodes next to the gap
// hold material of both boxes; with one DOF copy per connected part of the material the
// free box falls freely, with shared DOFs it hangs on the clamped one. dg on 0.1 m sliced
// cells (issue 35): the cells stay apart, and the moving-least-squares surface embedding
// must not reach across the gap for samples of the other box.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli/cli_support.hpp"

namespace altfem::test {
namespace {

int free_fall_check(const std::string& out) {
  const std::string check = "/usr/bin/python3 " + source_path("tests/cli/check_free_fall.py").string() + " " + out +
                            " 0.3 0.104 0 1 0.204 0.1 -9.81 0.01 10";
  return std::system(check.c_str());
}

int fcm_free_fall_check(bool topology_aware) {
  const auto out = fresh_directory(topology_aware ? "two_boxes_fcm_pieces" : "two_boxes_fcm_glued") / "run";
  const auto result = run_altfem(
      {"run", source_path("tests/cli/scenes/two_boxes.json").string(), "--method", "fcm", "--out", out.string(),
       "--set", std::string("discretization/fcm/topology_aware=") + (topology_aware ? "true" : "false")});
  EXPECT_EQ(result.exit_code, 0) << result.err;
  // The grid puts no cell across the gap whole, but nodes next to it get a copy per box.
  std::ifstream summary_file(out / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(summary_file);
  EXPECT_EQ(summary["facts"]["split_nodes"].get<int>() > 0, topology_aware);
  return free_fall_check(out.string());
}

TEST(FcmTopologyAware, TheFreeBoxOfTwoBoxesSharingCellsFallsFreely) {
  EXPECT_EQ(fcm_free_fall_check(true), 0) << "the free box did not fall freely (see output above)";
  EXPECT_NE(fcm_free_fall_check(false), 0) << "with shared DOFs the free box should hang on the clamped one";
}

class BodiesApart : public ::testing::TestWithParam<std::string> {};

TEST_P(BodiesApart, TheFreeBoxOfTwoBoxesFallsFreely) {
  const std::string method = GetParam();
  const auto out = fresh_directory("two_boxes_apart_" + method) / "run";
  const auto result = run_altfem({"run", source_path("tests/cli/scenes/two_boxes.json").string(), "--method", method,
                                  "--out", out.string(), "--set", "discretization/dg/mesh=slice", "--set",
                                  R"(discretization/dg/slice={"cell_size": 0.1})"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(free_fall_check(out.string()), 0) << "the free box did not fall freely (see output above)";
}

INSTANTIATE_TEST_SUITE_P(EveryMethod, BodiesApart, ::testing::Values("fem", "fcm", "dg", "harmonic"));

}  // namespace
}  // namespace altfem::test
