// The cost of events (issue #32, docs/architecture.md "Events") for every method on one
// scene, against the method's original set-up (medians over the repetitions):
//   - set-up: building the run (`Simulation`: the method from the scene, its loads, the
//     linear solver, the integrator);
//   - rebuild: the event that changes nothing (`Simulation::rebuild`: the method rebuilt
//     on the mesh it hands back, the state transferred) — target ≤ 1.2 × set-up;
//   - release: releasing the scene's last condition, by its phases (a release
//     re-integrates nothing: integration and transfer 0).
// The rebuild and release times include measuring what the event conserved (the
// method's mass and volume once per method, the momentum and energy before and after).
//
//   bench_events [--scene FILE] [--repetitions N] [--method NAME] [--set KEY=VALUE ...]
//
// The scene's last boundary condition is released after one step; it must be strong
// in every method (dg: --set discretization/dg/conditions=strong).
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "app/method_registry.hpp"
#include "bench/median.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/scene/scene_override.hpp"
#include "shared/simulation/simulation.hpp"

namespace {

using namespace altfem;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Timings {
  std::vector<double> setup, rebuild, release;
  EventPhases rebuild_phases, release_phases;
  long long dofs = 0;
};

Timings measure(const Scene& scene, const SceneGeometry& geometry, const MethodDescription& method, int repetitions) {
  Timings timings;
  SceneEvent release;
  release.condition = static_cast<int>(scene.dirichlet.size()) - 1;
  release.pointer = "/events/0";
  for (int repetition = 0; repetition < repetitions; ++repetition) {
    auto start = std::chrono::steady_clock::now();
    Simulation simulation(scene, geometry, std::string(method.scene_block.name), method.factory, method.rebuild);
    timings.setup.push_back(seconds_since(start));
    timings.dofs = simulation.discretization().dof_count();
    simulation.integrator().step(simulation.state());
    start = std::chrono::steady_clock::now();
    timings.rebuild_phases = simulation.rebuild().seconds;
    timings.rebuild.push_back(seconds_since(start));
    start = std::chrono::steady_clock::now();
    timings.release_phases = simulation.apply(release).seconds;
    timings.release.push_back(seconds_since(start));
  }
  return timings;
}

}  // namespace

int main(int argc, char** argv) {
  std::string scene_file = std::string(ALTFEM_SOURCE_DIR) + "/tests/verify/events/scenes/held_cantilever.json";
  std::string only;
  int repetitions = 3;
  std::vector<SceneOverride> overrides;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--scene")) scene_file = argv[i + 1];
    else if (!std::strcmp(argv[i], "--repetitions")) repetitions = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--method")) only = argv[i + 1];
    else if (!std::strcmp(argv[i], "--set")) overrides.push_back(parse_scene_override(argv[i + 1]));
  }
  Scene scene = load_scene(scene_file, overrides);
  scene.events.clear();
  const SceneGeometry geometry = load_scene_geometry(scene);
  std::printf("scene %s, %d repetitions, medians in seconds\n", scene.name.c_str(), repetitions);
  std::printf("%-9s %8s %9s %9s %7s | rebuild: %11s %9s %9s | %9s %11s %9s\n", "method", "dofs", "set-up", "rebuild",
              "ratio", "integration", "transfer", "pattern", "release", "integration", "pattern");
  for (const MethodDescription& method : cli::registered_methods()) {
    if (!only.empty() && method.scene_block.name != only) continue;
    const Timings timings = measure(scene, geometry, method, repetitions);
    const double setup = bench::median(timings.setup), rebuild = bench::median(timings.rebuild);
    std::printf("%-9s %8lld %9.4f %9.4f %7.2f | %20.4f %9.4f %9.4f | %9.5f %11.5f %9.5f\n",
                std::string(method.scene_block.name).c_str(), timings.dofs, setup, rebuild, rebuild / setup,
                timings.rebuild_phases.integration, timings.rebuild_phases.transfer, timings.rebuild_phases.pattern,
                bench::median(timings.release), timings.release_phases.integration, timings.release_phases.pattern);
  }
  return 0;
}
