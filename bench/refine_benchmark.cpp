// The cost of a refine event (issue #34; Kaufmann et al. 2009 §9.3, Martin et al. 2008 §8)
// for the methods that refine, every cell of a bar split 1→8 (or 1→2), medians over the
// repetitions, by phase: geometry (marking by the stress and splitting the mesh,
// split_polyhedral_cells), integration (the method rebuilt on the refined mesh), transfer,
// pattern (loads, linear solver, integrator), and the whole event; then the surface's
// embedding on the refined mesh, which a method builds when the first surface frame after
// the event needs it (EmbeddedSurface), and a run without surface frames never. Targets: 1,000 cells
// 1→8 in ≤ 1 s on 2 cores for dg and harmonic, ≤ 0.5 s for fem and fcm grids (fem Hex8 and
// Hex27, fcm Hex8 and Hex20 here: the forest split and balanced, hanging nodes constrained,
// refine_hexahedral_grid; fcm's grid is the bar's bounds grown by 5%, so its boundary cells
// are cut and get new rules).
//
//   bench_refine [--cells N] [--split 1to8|1to2] [--repetitions R] [--method NAME|"fem hex8"|…]
//
// (fem and fcm run with 1to8 only: they do not halve hexahedra.)
//
// The bar is 1 × 0.1 × 0.1 m of N cells (--cells 1000: 40 × 5 × 5), loaded by an affine
// displacement, so that every cell carries the same stress above the threshold 0.
#include <chrono>
#include <cmath>
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
  std::vector<double> geometry, integration, transfer, pattern, total, embedding;
  long long cells_before = 0, cells_after = 0, dofs_after = 0;
};

Timings measure(const Scene& scene, const SceneGeometry& geometry, const std::string& name, int repetitions) {
  const MethodDescription& method = cli::find_method(name);
  Timings timings;
  for (int repetition = 0; repetition < repetitions; ++repetition) {
    Simulation simulation(scene, geometry, name, method.factory, method.rebuild);
    simulation.state().displacement = simulation.method().interpolate(
        [](const Eigen::Vector3d& x) -> Eigen::Vector3d { return Eigen::Vector3d(1e-3, 3e-4, -2e-4) * x.x(); });
    const auto start = std::chrono::steady_clock::now();
    const EventRecord record = simulation.apply(scene.events.at(0));
    timings.total.push_back(seconds_since(start));
    timings.geometry.push_back(record.seconds.geometry);
    timings.integration.push_back(record.seconds.integration);
    timings.transfer.push_back(record.seconds.transfer);
    timings.pattern.push_back(record.seconds.pattern);
    const auto embedding_start = std::chrono::steady_clock::now();
    simulation.method().embedded_displacement(simulation.state().displacement);
    timings.embedding.push_back(seconds_since(embedding_start));
    timings.cells_after = record.facts["cells"].get<long long>();
    timings.cells_before = timings.cells_after - 7 * record.facts["marked_cells"].get<long long>();
    timings.dofs_after = record.dofs_after;
  }
  return timings;
}

}  // namespace

int main(int argc, char** argv) {
  int cells = 1000, repetitions = 3;
  std::string split = "1to8", only;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--cells")) cells = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--split")) split = argv[i + 1];
    else if (!std::strcmp(argv[i], "--repetitions")) repetitions = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--method")) only = argv[i + 1];
  }
  // n × n/8 × n/8 cells of the 1 × 0.1 × 0.1 bar (cubes for n a multiple of 8 … roughly).
  const int across = std::max(1, static_cast<int>(std::lround(std::cbrt(cells / 8.0))));
  const int along = std::max(1, cells / (across * across));
  const std::string resolution =
      "[" + std::to_string(along) + ", " + std::to_string(across) + ", " + std::to_string(across) + "]";
  // The scene for a label: "dg", "harmonic", or a grid method and its cell ("fem hex27").
  const auto bar = [&](const std::string& label) {
    std::vector<SceneOverride> overrides{
        parse_scene_override("events/0/refine/split=\"" + split + "\""),
        parse_scene_override("discretization/dg/resolution=" + resolution),
        parse_scene_override("discretization/harmonic/convert/resolution=" + resolution)};
    if (label.starts_with("fem "))
      overrides.push_back(parse_scene_override("discretization/fem={\"element\": \"" + label.substr(4) +
                                               "\", \"mesh\": \"grid\", \"resolution\": " + resolution + "}"));
    if (label.starts_with("fcm "))
      overrides.push_back(parse_scene_override("discretization/fcm={\"cell\": \"" + label.substr(4) +
                                               "\", \"resolution\": " + resolution + ", \"margin\": 0.05}"));
    return load_scene(std::string(ALTFEM_SOURCE_DIR) + "/tests/verify/events/scenes/cantilever_refine.json", overrides);
  };
  const Scene scene = bar("dg");
  const SceneGeometry geometry = load_scene_geometry(scene);
  std::printf("bar of %s cells, every cell split %s, %d repetitions, medians in seconds\n", resolution.c_str(),
              split.c_str(), repetitions);
  std::printf("%-9s %7s %7s %9s | %9s %11s %9s %9s %9s | %12s | %9s\n", "method", "cells", "after", "dofs", "geometry",
              "integration", "transfer", "pattern", "event", "per 1000 (s)", "embedding");
  for (const std::string label : {"dg", "harmonic", "fem hex8", "fem hex27", "fcm hex8", "fcm hex20"}) {
    const std::string name = label.substr(0, label.find(' '));
    const bool grid = name == "fem" || name == "fcm";
    if ((!only.empty() && name != only && label != only) || (grid && split != "1to8")) continue;
    const Timings timings = measure(grid ? bar(label) : scene, geometry, name, repetitions);
    const double event = bench::median(timings.total);
    std::printf("%-9s %7lld %7lld %9lld | %9.4f %11.4f %9.4f %9.4f %9.4f | %12.4f | %9.4f\n", label.c_str(),
                timings.cells_before, timings.cells_after, timings.dofs_after, bench::median(timings.geometry),
                bench::median(timings.integration), bench::median(timings.transfer), bench::median(timings.pattern),
                event, event * 1000.0 / static_cast<double>(timings.cells_before), bench::median(timings.embedding));
  }
  return 0;
}
