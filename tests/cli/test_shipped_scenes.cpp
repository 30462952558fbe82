// Every shipped scene runs with every method (docs/conventions.md, "One scene, every
// method"; issues 18, 19 and 38): `altfem run --method fem|fcm|dg|harmonic`, one time step
// (the scene's events moved before it, so they run too), output/volume off, at small sizes
// through --set: the cell sizes the scene's method block gives doubled (fem's mesh, fcm's
// embedded tetrahedra, whose intersections with the cut cells make its rules: the scene's
// own sizes took up to 21 s to build in `altfem check`), dg's sliced meshes at 4 cells per
// side. What is left is mostly the shape's common surface (SceneGeometry::common_surface:
// 5-6 s for the hollow ball's holes, whatever the method). dg slices surfaces and shapes
// other than boxes by default (Kaufmann et al. 2009, §9.2), converts box grids and volume
// mesh files; harmonic converts by default (its sliced meshes are run by
// verify_manufactured). Their bases are no longer the cost on sliced scenes
// (bench_polyhedral_element: ~5 ms per cut cell), but a cut cell bounded by many surface
// facets carries a cone rule of 4 points per facet triangle and all its nodes, so each
// Newton iteration's assembly grows with the surface's detail: at the default slice
// resolution one step of the armadillo took over 300 s on one core, the hollow ball 99 s
// (30 Newton iterations), against 0.3-5 s converted.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <tuple>

#include "tests/cli/cli_support.hpp"

namespace altfem::test {
namespace {

struct SceneRun {
  std::string scene;  ///< file name under scenes/
  std::string method;
  bool slice;  ///< dg, harmonic: the mesh is expected to be sliced
};

// Names a parameter by its scene and method in test output (instead of its bytes).
void PrintTo(const SceneRun& run, std::ostream* out) { *out << run.scene << " " << run.method; }

nlohmann::json read_json(const std::filesystem::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

// dg's default mesh rule (docs/scene-schema.md, dg/mesh): a surface, or a shape that is not
// a box, unless the scene's dg block names the mesh or a converted mesh's keys.
bool sliced_by_default(const nlohmann::json& scene) {
  const nlohmann::json& geometry = scene["geometry"];
  const nlohmann::json dg = scene.contains("discretization")
                                ? scene["discretization"].value("dg", nlohmann::json::object())
                                : nlohmann::json::object();
  for (const char* key : {"mesh", "element", "resolution", "max_cell_size"})
    if (dg.contains(key)) return dg.value("mesh", "") == "slice";
  return geometry.contains("surface") || (geometry.contains("shape") && !geometry["shape"].contains("box"));
}

// harmonic converts the fem mesh unless its block asks for a slicing.
bool harmonic_sliced(const nlohmann::json& scene) {
  return scene.contains("discretization") && scene["discretization"].contains("harmonic") &&
         scene["discretization"]["harmonic"].value("mesh", "") == "slice";
}

// A shape of boxes only (a box, or a union, intersection or difference of them): sliced on
// a grid whose planes hold its faces, it has no cut cells.
bool built_of_boxes(const nlohmann::json& shape) {
  if (shape.contains("box")) return true;
  for (const char* operation : {"union", "intersection", "difference"})
    if (shape.contains(operation)) return std::all_of(shape[operation].begin(), shape[operation].end(), built_of_boxes);
  return false;
}

std::vector<SceneRun> scene_runs() {
  std::vector<SceneRun> runs;
  for (const auto& entry : std::filesystem::directory_iterator(source_path("scenes"))) {
    if (entry.path().extension() != ".json") continue;
    const nlohmann::json scene = read_json(entry.path());
    const std::string name = entry.path().filename().string();
    for (const char* method : {"fem", "fcm"}) runs.push_back({name, method, false});
    runs.push_back({name, "dg", sliced_by_default(scene)});
    runs.push_back({name, "harmonic", harmonic_sliced(scene)});
  }
  std::sort(runs.begin(), runs.end(), [](const SceneRun& a, const SceneRun& b) {
    return std::tie(a.scene, a.method) < std::tie(b.scene, b.method);
  });
  return runs;
}

class ShippedScene : public testing::TestWithParam<SceneRun> {};

// The events a dynamic scene's one-step run keeps, from its first.
constexpr std::size_t max_events = 5;

TEST_P(ShippedScene, RunsWithExitZeroAndFiniteOutput) {
  const SceneRun& run = GetParam();
  const std::filesystem::path scene_file = source_path("scenes/" + run.scene);
  const nlohmann::json scene = read_json(scene_file);
  const auto out = fresh_directory("scene_" + run.method) / run.scene;
  std::vector<std::string> arguments{"run",   scene_file.string(), "--method", run.method,
                                     "--out", out.string(),        "--set",    "output/volume=false"};
  const std::string block = "discretization/" + run.method + "/";
  if (run.slice) arguments.insert(arguments.end(), {"--set", block + "slice/resolution=4"});
  const nlohmann::json discretization = scene.value("discretization", nlohmann::json::object());
  const nlohmann::json own = discretization.value(run.method, nlohmann::json::object());
  for (const char* size : {"max_cell_size", "embedded_cell_size"})
    if (own.contains(size))
      arguments.insert(arguments.end(), {"--set", block + size + "=" + std::to_string(2 * own[size].get<double>())});
  nlohmann::json events = scene.value("events", nlohmann::json::array());
  const bool hexahedral_grid = own.value("mesh", "") == "grid" && own.value("element", "").starts_with("hex");
  if (run.method == "fcm" || (run.method == "fem" && !hexahedral_grid)) {
    // They refuse refinement before the run (fcm: no hanging-node constraints yet; fem: only
    // hexahedral grids refine, issue #34): the scene runs without its refine events.
    nlohmann::json kept = nlohmann::json::array();
    for (const nlohmann::json& event : events)
      if (!event.contains("refine")) kept.push_back(event);
    events = kept;
    arguments.insert(arguments.end(), {"--set", "events=" + events.dump()});
  }
  if (scene.contains("time") && !scene["time"].value("static", false)) {
    // One step; the scene's first events act before it, so they run too (the pencil's
    // 50 cuts multiply fcm's and fem's embedded tetrahedra near its tip: minutes).
    arguments.insert(arguments.end(), {"--set", "time/steps=1"});
    if (events.size() > max_events) events.erase(events.begin() + max_events, events.end());
    for (nlohmann::json& event : events) event["time"] = 0;
    arguments.insert(arguments.end(), {"--set", "events=" + events.dump()});
  }
  const CommandResult result = run_altfem(arguments);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json summary = read_json(out / "summary.json");
  EXPECT_EQ(summary["status"], "ok");
  EXPECT_GT(summary["dofs"].get<long long>(), 0);
  std::size_t event_count = 0;  // a static refinement's cycles are one event each
  for (const nlohmann::json& event : events)
    event_count += event.contains("refine") ? event["refine"].value("cycles", 1) : 1;
  EXPECT_EQ(summary["events"].size(), event_count);
  if (run.method == "dg" || run.method == "harmonic") {
    EXPECT_EQ(summary["facts"]["source"], run.slice ? "slice" : "convert");
    EXPECT_EQ(summary["options"]["discretization"][run.method]["mesh"] == "slice", run.slice);
    if (run.slice && !(scene["geometry"].contains("shape") && built_of_boxes(scene["geometry"]["shape"]))) {
      EXPECT_GT(summary["facts"]["slicing"]["cut_pieces"].get<int>(), 0);
    }
  }
  // nlohmann writes a NaN as null and the log prints it as "nan".
  std::stringstream text;
  text << std::ifstream(out / "summary.json").rdbuf() << std::ifstream(out / "log.txt").rdbuf();
  for (const char* token : {"null", "nan", "inf"})
    EXPECT_EQ(text.str().find(token), std::string::npos) << run.scene << " output holds " << token;
}

std::string run_name(const testing::TestParamInfo<SceneRun>& info) {
  return info.param.scene.substr(0, info.param.scene.find('.')) + "_" + info.param.method;
}

INSTANTIATE_TEST_SUITE_P(EveryMethod, ShippedScene, testing::ValuesIn(scene_runs()), run_name);

// The bunny sliced at the default resolution with harmonic: some cut cells are not
// star-shaped about their centroid (5 of them about no point), whose cone rules had
// negative weights and made the lumped mass of 19 nodes negative (exit 1, "DiagonalMass").
TEST(PolyhedralScene, HarmonicRunsOnTheSlicedBunny) {
  const auto out = fresh_directory("polyhedral_harmonic_slice") / "bunny";
  const CommandResult result = run_altfem({"run", source_path("scenes/bunny.json").string(), "--method", "harmonic",
                                           "--out", out.string(), "--set", "discretization/harmonic/mesh=slice",
                                           "--set", "output/volume=false", "--set", "time/steps=1"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json summary = read_json(out / "summary.json");
  EXPECT_EQ(summary["status"], "ok");
  EXPECT_GT(summary["elements"]["mfs_polyhedron"].get<int>(), 0);
}

}  // namespace
}  // namespace altfem::test
