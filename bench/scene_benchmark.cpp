// Whole-solve scene benchmarks (issue #3/#9), through run_simulation, the pipeline
// `altfem run` uses:
//   - the cantilever (scenes/cantilever.json: 1 × 0.1 × 0.1 m, clamped at x = 0, linear,
//     static, gravity) with Hex8, Hex20, Tet4 and Tet10 at three grid resolutions each:
//     DOFs, mean vertical displacement of the free end face and its difference from a
//     fine Hex27 reference, phase times (medians) and peak RSS;
//   - the Tet10 twisting beam (scenes/twisting_beam.json, Stable Neo-Hookean, backward
//     Euler): seconds per Newton iteration, split into assembly and linear solve.
//
//   bench_scene [--repetitions N] [--beam-steps S] [--beam-cell-size H]
//
// Every case runs in a child process of its own (this program with --case ...), so
// that its peak RSS is its own and not the largest case's so far.
#include <omp.h>

#include <unistd.h>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench/median.hpp"
#include "bench/process_usage.hpp"
#include "shared/fem/method/fem_method.hpp"
#include "shared/scene/scene.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/simulation/run_simulation.hpp"

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// The mean u_z over the nodes on the end face x = max x of the fem mesh (its volume
// grid: points are the nodes): a node average, not an area-weighted one, but the same
// estimator for every element type.
double end_face_displacement(const altfem::MethodInstance& method, const Eigen::VectorXd& u) {
  const altfem::UnstructuredGrid grid = method.volume_grid(u);
  const Eigen::MatrixXd& nodes = grid.points;
  const double end = nodes.col(0).maxCoeff();
  double sum = 0;
  int count = 0;
  for (Eigen::Index node = 0; node < nodes.rows(); ++node)
    if (nodes(node, 0) > end - 1e-9) {
      sum += u[3 * node + 2];
      ++count;
    }
  return sum / count;
}

// Forwards to the fem method and measures the end face of every displacement
// run_simulation hands to embedded_displacement (it does so for every frame it writes,
// the final state last), so the benchmark reads the solution without parsing VTU
// files. run_simulation destroys the method before returning: the figure goes to
// `end_face` which outlives it.
class RecordingMethod final : public altfem::MethodInstance {
public:
  RecordingMethod(std::unique_ptr<altfem::MethodInstance> inner, double& end_face)
      : inner_(std::move(inner)), end_face_(end_face) {}

  const altfem::Discretization& discretization() const override { return inner_->discretization(); }
  json element_counts() const override { return inner_->element_counts(); }
  long long quadrature_points() const override { return inner_->quadrature_points(); }
  double quadrature_seconds() const override { return inner_->quadrature_seconds(); }
  altfem::UnstructuredGrid volume_grid(const Eigen::VectorXd& u) const override { return inner_->volume_grid(u); }
  const altfem::SurfaceMesh& embedded_surface() const override { return inner_->embedded_surface(); }
  const altfem::ElementBasisEvaluator& basis_evaluator() const override { return inner_->basis_evaluator(); }
  Eigen::MatrixXd embedded_displacement(const Eigen::VectorXd& u) const override {
    end_face_ = end_face_displacement(*inner_, u);
    return inner_->embedded_displacement(u);
  }
  Eigen::VectorXd interpolate(const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& field) const override {
    return inner_->interpolate(field);
  }

private:
  std::unique_ptr<altfem::MethodInstance> inner_;
  double& end_face_;
};

struct RunResult {
  json summary;
  double end_face_displacement = 0;
};

// One run of `scene` with fem, writing only the (small) surface frames into a
// temporary folder that is removed afterwards.
RunResult run_once(altfem::Scene scene) {
  scene.output.volume = false;
  scene.output.surface = true;
  scene.output.every = 1000000;  // the last frame only (run_simulation always writes the last step)
  const auto start = std::chrono::steady_clock::now();
  const altfem::SceneGeometry geometry = altfem::load_scene_geometry(scene);
  const double loading = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  RunResult result;
  const altfem::MethodFactory factory = [&](const altfem::Scene& s, const altfem::SceneGeometry& g) {
    return std::make_unique<RecordingMethod>(altfem::make_fem_method(s, g), result.end_face_displacement);
  };
  const fs::path directory = fs::temp_directory_path() / ("altfem-bench-scene-" + std::to_string(getpid()));
  result.summary = altfem::run_simulation(scene, geometry, "fem", factory, directory, loading);
  fs::remove_all(directory);
  return result;
}

// Child: runs one case `repetitions` times and prints one line "RESULT {json}" with the
// medians of every phase.
int run_case(const std::vector<std::string>& arguments, int repetitions) {
  altfem::Scene scene = altfem::load_scene(fs::path(ALTFEM_SOURCE_DIR) / "scenes" / (arguments[0] + ".json"));
  // The fem block is resolved by the method from scene.resolved (fem_spec).
  json& fem = scene.resolved["discretization"]["fem"];
  if (arguments[0] == "cantilever") {
    fem = {{"element", arguments[1]},
           {"mesh", "grid"},
           {"resolution", {std::stoi(arguments[2]), std::stoi(arguments[3]), std::stoi(arguments[4])}}};
  } else {
    fem["max_cell_size"] = std::stod(arguments[1]);
    scene.time.steps = std::stoi(arguments[2]);
  }
  std::vector<RunResult> runs;
  const double cpu_start = altfem::bench::process_cpu_seconds();
  for (int r = 0; r < repetitions; ++r) runs.push_back(run_once(scene));
  const double cpu_per_run = (altfem::bench::process_cpu_seconds() - cpu_start) / repetitions;
  json out = {{"dofs", runs[0].summary["dofs"]},
              {"elements", runs[0].summary["elements"]},
              {"newton_iterations", runs[0].summary["newton_iterations"]},
              {"end_face_displacement", runs[0].end_face_displacement},
              {"repetitions", repetitions},
              {"threads", omp_get_max_threads()},
              {"peak_rss_gib", altfem::bench::peak_resident_gib()},
              {"cpu_seconds_per_run", cpu_per_run}};
  for (const char* phase : {"setup", "quadrature", "assembly", "analysis", "factorisation", "solve", "total"}) {
    std::vector<double> seconds;
    for (const RunResult& run : runs) seconds.push_back(run.summary["timings_s"][phase].get<double>());
    out["seconds"][phase] = altfem::bench::median(seconds);
  }
  std::vector<double> linear;
  for (const RunResult& run : runs)
    linear.push_back(run.summary["timings_s"]["assembly"].get<double>() +
                     run.summary["timings_s"]["factorisation"].get<double>() +
                     run.summary["timings_s"]["solve"].get<double>());
  out["seconds"]["assembly+factorisation+solve"] = altfem::bench::median(linear);
  // Above 1 only when the process waited for a core: the machine was loaded.
  out["wall_over_cpu"] = out["seconds"]["total"].get<double>() / cpu_per_run;
  std::printf("RESULT %s\n", out.dump().c_str());
  return 0;
}

// Parent: runs `arguments` as a child process and returns its RESULT.
json spawn_case(const std::string& arguments, int repetitions) {
  const std::string command = fs::read_symlink("/proc/self/exe").string() + " --repetitions " +
                              std::to_string(repetitions) + " --case " + arguments;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return nullptr;
  std::string line, result;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) {
    line += buffer;
    if (line.back() == '\n') {
      if (line.rfind("RESULT ", 0) == 0) result = line.substr(7);
      line.clear();
    }
  }
  const int status = pclose(pipe);
  if (status != 0 || result.empty()) {
    std::fprintf(stderr, "bench_scene: case '%s' failed (status %d)\n", arguments.c_str(), status);
    return nullptr;
  }
  return json::parse(result);
}

struct CantileverCase {
  const char* element;
  int nx, ny, nz;
};

void cantilever_table(int repetitions) {
  // Three resolutions per element; Hex20 50×5×5 is the ~20k-DOF target case.
  const CantileverCase cases[] = {
      {"hex8", 20, 2, 2},  {"hex8", 40, 4, 4},  {"hex8", 80, 8, 8},  {"hex20", 20, 2, 2},
      {"hex20", 30, 3, 3}, {"hex20", 50, 5, 5}, {"tet4", 20, 2, 2},  {"tet4", 40, 4, 4},
      {"tet4", 80, 8, 8},  {"tet10", 20, 2, 2}, {"tet10", 30, 3, 3}, {"tet10", 50, 5, 5},
  };
  auto arguments = [](const CantileverCase& c) {
    return std::string("cantilever ") + c.element + " " + std::to_string(c.nx) + " " + std::to_string(c.ny) + " " +
           std::to_string(c.nz);
  };
  const CantileverCase reference_case{"hex27", 80, 8, 8};
  const json reference = spawn_case(arguments(reference_case), 1);
  if (reference.is_null()) return;
  const double w_reference = reference["end_face_displacement"].get<double>();
  std::printf("\nCantilever (scenes/cantilever.json, linear, static), %d threads; medians of %d runs.\n",
              reference["threads"].get<int>(), repetitions);
  std::printf("Reference: hex27 80x8x8, %d DOFs, mean end-face u_z = %.6e m\n", reference["dofs"].get<int>(),
              w_reference);
  std::printf("Seconds are wall-clock medians; wall/CPU > 1 means the run waited for a core (a loaded machine).\n");
  std::printf("%-16s %8s %13s %10s %8s %8s %8s %8s %8s %8s %8s %8s\n", "case", "DOFs", "u_z end [m]", "rel.diff",
              "setup", "assembly", "analysis", "factor.", "solve", "a+f+s", "RSS GiB", "wall/CPU");
  for (const CantileverCase& c : cases) {
    const json r = spawn_case(arguments(c), repetitions);
    if (r.is_null()) continue;
    const json& s = r["seconds"];
    const double w = r["end_face_displacement"].get<double>();
    const std::string name =
        std::string(c.element) + " " + std::to_string(c.nx) + "x" + std::to_string(c.ny) + "x" + std::to_string(c.nz);
    std::printf("%-16s %8d %13.6e %10.2e %8.3f %8.3f %8.3f %8.3f %8.3f %8.3f %8.3f %8.2f\n", name.c_str(),
                r["dofs"].get<int>(), w, (w - w_reference) / std::abs(w_reference), s["setup"].get<double>(),
                s["assembly"].get<double>(), s["analysis"].get<double>(), s["factorisation"].get<double>(),
                s["solve"].get<double>(), s["assembly+factorisation+solve"].get<double>(),
                r["peak_rss_gib"].get<double>(), r["wall_over_cpu"].get<double>());
    if (std::strcmp(c.element, "hex20") == 0 && c.nx == 50)
      std::printf("  target: hex20 ~20k DOFs, assembly+factorisation+solve <= 1.0 s: %s\n",
                  s["assembly+factorisation+solve"].get<double>() <= 1.0 ? "MET" : "MISSED");
  }
}

void twisting_beam(int repetitions, int steps, const std::string& cell_size) {
  const json r = spawn_case("twisting_beam " + cell_size + " " + std::to_string(steps), repetitions);
  if (r.is_null()) return;
  const json& s = r["seconds"];
  const double iterations = r["newton_iterations"].get<double>();
  const double assembly = s["assembly"].get<double>() / iterations;
  const double linear =
      (s["analysis"].get<double>() + s["factorisation"].get<double>() + s["solve"].get<double>()) / iterations;
  std::printf(
      "\nTwisting beam (scenes/twisting_beam.json, tet10, max_cell_size %s, stable Neo-Hookean, backward "
      "Euler), first %d steps, %d threads; medians of %d runs.\n",
      cell_size.c_str(), steps, r["threads"].get<int>(), repetitions);
  std::printf("  %s, %d DOFs, %d Newton iterations\n", r["elements"].dump().c_str(), r["dofs"].get<int>(),
              static_cast<int>(iterations));
  std::printf(
      "  per Newton iteration: assembly (energy+gradient+Hessian) %.3f s, linear solve (analysis+"
      "factorisation+solve) %.3f s [analysis %.3f s total, factorisation %.3f s, solve %.3f s per "
      "iteration]\n",
      assembly, linear, s["analysis"].get<double>(), s["factorisation"].get<double>() / iterations,
      s["solve"].get<double>() / iterations);
  std::printf("  setup %.3f s; total %.3f s; peak RSS %.3f GiB; wall/CPU %.2f\n", s["setup"].get<double>(),
              s["total"].get<double>(), r["peak_rss_gib"].get<double>(), r["wall_over_cpu"].get<double>());
}

}  // namespace

int main(int argc, char** argv) {
  int repetitions = 3, beam_steps = 3;
  std::string beam_cell_size = "0.035";  // the scene's own: ~30k DOFs, as issue #3 asks
  std::vector<std::string> case_arguments;
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument == "--repetitions" && i + 1 < argc) {
      repetitions = std::max(1, std::atoi(argv[++i]));
    } else if (argument == "--beam-steps" && i + 1 < argc) {
      beam_steps = std::max(1, std::atoi(argv[++i]));
    } else if (argument == "--beam-cell-size" && i + 1 < argc) {
      beam_cell_size = argv[++i];
    } else if (argument == "--case") {
      case_arguments.assign(argv + i + 1, argv + argc);
      break;
    } else {
      std::fprintf(stderr, "usage: bench_scene [--repetitions N] [--beam-steps S] [--beam-cell-size H]\n");
      return 2;
    }
  }
  if (!case_arguments.empty()) return run_case(case_arguments, repetitions);
  cantilever_table(repetitions);
  twisting_beam(repetitions, beam_steps, beam_cell_size);
  return 0;
}
