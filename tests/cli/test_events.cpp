// `altfem run` with events (docs/scene-schema.md, "Events"): a release is a line of
// log.txt and an entry of summary.json, the frames go on after it, and a release a
// method cannot carry out is one line of bad input before anything is written.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/cli/cli_support.hpp"

namespace altfem::test {
namespace {

const std::string held_cantilever = "tests/verify/events/scenes/held_cantilever.json";

std::string read_text(const std::filesystem::path& file) {
  std::stringstream text;
  text << std::ifstream(file).rdbuf();
  return text.str();
}

TEST(Events, ReleaseIsLoggedSummarisedAndTheFramesGoOn) {
  const auto out = fresh_directory("events-release") / "run";
  const auto result = run_altfem({"run", source_path(held_cantilever).string(), "--method", "fem", "--out",
                                  out.string(), "--set", "time/steps=30", "--set", "output/every=10"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json summary = read_summary(out);
  ASSERT_EQ(summary["events"].size(), 1u);
  const nlohmann::json& event = summary["events"][0];
  EXPECT_EQ(event["kind"], "release");
  EXPECT_EQ(event["target"], "tip");
  EXPECT_EQ(event["pointer"], "/events/0");
  EXPECT_EQ(event["step"], 25);  // the first step boundary at or after 0.1 s with dt = 0.004 s
  EXPECT_EQ(event["dofs"]["before"], event["dofs"]["after"]);
  EXPECT_EQ(event["quadrature_points"]["before"], summary["quadrature_points"]);  // nothing re-integrated
  EXPECT_EQ(event["quadrature_points"]["after"], summary["quadrature_points"]);
  EXPECT_GT(event["constrained_dofs"]["before"].get<int>(), event["constrained_dofs"]["after"].get<int>());
  for (const char* phase : {"geometry", "integration", "pattern", "transfer"})
    EXPECT_GE(event["seconds"][phase].get<double>(), 0.0) << phase;
  EXPECT_GT(event["seconds"]["measures"].get<double>(), 0.0);  // the body measured before and after
  for (const char* measure : {"mass_change", "volume_change", "momentum_change", "energy_before_j", "energy_jump_j"})
    EXPECT_TRUE(event["conserved"].contains(measure)) << measure;
  // Counted honestly across the release: the pattern is the same (no second analysis),
  // the eliminated matrix is not (one more factorisation of the linear material).
  EXPECT_EQ(summary["counts"]["analyses"], 1);
  EXPECT_EQ(summary["counts"]["factorisations"], 2);
  const std::string log = read_text(out / "log.txt");
  EXPECT_NE(log.find("# event release 'tip' at t = 0.1 after step 25"), std::string::npos) << log;
  // Frames 0, 10, 20, 30: the volume collection lists four.
  const std::string volume = read_text(out / "volume.pvd");
  std::size_t frames = 0;
  for (std::size_t at = volume.find("<DataSet"); at != std::string::npos; at = volume.find("<DataSet", at + 1))
    ++frames;
  EXPECT_EQ(frames, 4u);
  const std::string check =
      "/usr/bin/python3 " + source_path("tests/cli/check_run_output.py").string() + " " + out.string();
  EXPECT_EQ(std::system(check.c_str()), 0) << "meshio disagrees with summary.json (see output above)";
}

TEST(Events, AWeakConditionCannotBeReleased) {
  const auto out = fresh_directory("events-weak") / "run";
  const auto result = run_altfem({"run", source_path(held_cantilever).string(), "--method", "dg", "--out", out.string(),
                                  "--set", "discretization/dg/conditions=weak"});
  EXPECT_EQ(result.exit_code, 2) << result.err;
  const auto lines = lines_of(result.err);
  ASSERT_EQ(lines.size(), 1u) << result.err;
  EXPECT_NE(lines[0].find("/events/0/release: cannot release 'tip'"), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("weakly"), std::string::npos) << lines[0];
  EXPECT_FALSE(std::filesystem::exists(out)) << "bad input wrote output";
}

TEST(Events, AStaticSceneCannotReleaseItsLastSupport) {
  const auto out = fresh_directory("events-last-support") / "run";
  const auto result = run_altfem({"run", source_path(held_cantilever).string(), "--method", "fem", "--out",
                                  out.string(), "--set", R"(time={"static": true, "load_steps": 2})", "--set",
                                  R"(events=[{"time": 0, "release": "tip"}, {"time": 1, "release": "clamp"}])"});
  EXPECT_EQ(result.exit_code, 2) << result.err;
  const auto lines = lines_of(result.err);
  ASSERT_EQ(lines.size(), 1u) << result.err;
  EXPECT_NE(lines[0].find("/events/1/release: cannot release 'clamp': nothing would hold the body"), std::string::npos)
      << lines[0];
  EXPECT_FALSE(std::filesystem::exists(out)) << "bad input wrote output";
}

TEST(Events, StaticLoadStepsWithAReleaseBetweenThem) {
  const auto out = fresh_directory("events-static") / "run";
  const auto result =
      run_altfem({"run", source_path(held_cantilever).string(), "--method", "fem", "--out", out.string(), "--set",
                  R"(time={"static": true, "load_steps": 4})", "--set", "events/0/time=2"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json summary = read_summary(out);
  EXPECT_EQ(summary["steps"], 4);
  ASSERT_EQ(summary["events"].size(), 1u);
  EXPECT_EQ(summary["events"][0]["step"], 2);
  // The load factor is the log's time: 0.25, 0.5, then the release, then 0.75 and 1.
  std::istringstream log(read_text(out / "log.txt"));
  std::vector<std::string> rows;
  for (std::string line; std::getline(log, line);)
    if (!line.empty() && line[0] != '#') rows.push_back(line.substr(0, line.find(' ', line.find(' ') + 1)));
    else if (line.rfind("# event", 0) == 0) rows.push_back("event");
  EXPECT_EQ(rows, (std::vector<std::string>{"1 0.25", "2 0.5", "event", "3 0.75", "4 1"}));
}

// A cut is summarised with its counts and logged; a method that does not cut refuses it
// before writing anything.
TEST(Events, ACutIsSummarisedAndAMethodThatCannotCutRefusesIt) {
  const std::string scene = source_path("tests/verify/events/scenes/cantilever_cut.json").string();
  const auto out = fresh_directory("events-cut") / "run";
  const auto cut = run_altfem({"run", scene, "--method", "dg", "--out", out.string()});
  ASSERT_EQ(cut.exit_code, 0) << cut.err;
  const nlohmann::json summary = read_summary(out);
  ASSERT_EQ(summary["events"].size(), 1u);
  const nlohmann::json& event = summary["events"][0];
  EXPECT_EQ(event["kind"], "cut");
  EXPECT_EQ(event["facts"]["crossed_cells"], 1);  // the plane x = 0.55 crosses one of dg's 10 cells
  EXPECT_EQ(summary["dofs"], event["dofs"]["after"]);
  EXPECT_EQ(summary["elements"]["k2_polyhedron"], 11);
  // fcm cuts its embedded tetrahedra: the cell [0.5, 0.6] of its 10 becomes two pieces.
  const auto fcm_out = fresh_directory("events-cut-fcm") / "run";
  const auto fcm = run_altfem({"run", scene, "--method", "fcm", "--out", fcm_out.string()});
  ASSERT_EQ(fcm.exit_code, 0) << fcm.err;
  const nlohmann::json fcm_summary = read_summary(fcm_out);
  EXPECT_GT(fcm_summary["events"][0]["facts"]["crossed_fragments"].get<int>(), 0);
  EXPECT_EQ(fcm_summary["elements"]["hex20"], 11);
  // `facts` are the method's before the cut, `facts_at_end` after it: the cut cell is kept as two.
  EXPECT_EQ(fcm_summary["facts"]["cells"]["split"], 0);
  EXPECT_EQ(fcm_summary["facts_at_end"]["cells"]["split"], 1);
  // fcm without topology-aware cells has no node copies to separate the sides.
  for (const std::string method : {"fcm"}) {
    const auto refused_out = fresh_directory("events-cut-" + method) / "run";
    const auto refused = run_altfem({"run", scene, "--method", method, "--out", refused_out.string(), "--set",
                                     "discretization/fcm/topology_aware=false"});
    EXPECT_EQ(refused.exit_code, 2) << refused.err;
    const auto lines = lines_of(refused.err);
    ASSERT_EQ(lines.size(), 1u) << refused.err;
    EXPECT_NE(lines[0].find("/events/0/cut: cannot cut with " + method), std::string::npos) << lines[0];
    EXPECT_FALSE(std::filesystem::exists(refused_out)) << "bad input wrote output";
  }
}

// A blade read from a surface file cuts as the scene says; a file that is not there, or a
// sweep of it, is one line of bad input naming the key, before anything is written.
TEST(Events, ASurfaceBladeCutsAndABadOneIsRefusedBeforeTheRun) {
  const std::string scene = source_path("tests/verify/events/scenes/cantilever_cut.json").string();
  const auto out = fresh_directory("events-cut-surface") / "run";
  const auto cut = run_altfem({"run", scene, "--method", "dg", "--out", out.string(), "--set",
                               R"(events=[{"time": 0.02, "cut": {"surface": "v_blade.obj"}}])"});
  ASSERT_EQ(cut.exit_code, 0) << cut.err;
  const nlohmann::json event = read_summary(out)["events"][0];
  EXPECT_EQ(event["kind"], "cut");
  EXPECT_EQ(event["facts"]["crossed_cells"], 2);  // the V crosses dg's cells [0.6, 0.7] and [0.7, 0.8]
  EXPECT_GT(event["facts"]["duplicated_nodes"].get<int>(), 0);
  const std::vector<std::pair<std::string, std::string>> refusals = {
      {R"({"surface": "no_such_blade.obj"})", "/events/0/cut/surface: expected a triangulated blade surface"},
      {R"({"surface": "v_blade.obj", "sweep": {"to_time": 0.04, "translation": [0, 0, 0.1]}})",
       "/events/0/cut/sweep: a surface blade"}};
  for (const auto& [blade, message] : refusals) {
    const auto refused_out = fresh_directory("events-cut-surface-refused") / "run";
    const auto refused = run_altfem({"run", scene, "--method", "dg", "--out", refused_out.string(), "--set",
                                     R"(events=[{"time": 0.02, "cut": )" + blade + "}]"});
    EXPECT_EQ(refused.exit_code, 2) << refused.err;
    const auto lines = lines_of(refused.err);
    ASSERT_EQ(lines.size(), 1u) << refused.err;
    EXPECT_NE(lines[0].find(message), std::string::npos) << lines[0];
    EXPECT_FALSE(std::filesystem::exists(refused_out)) << "bad input wrote output";
  }
}

}  // namespace
}  // namespace altfem::test
