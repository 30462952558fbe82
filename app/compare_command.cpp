#include "app/compare_command.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "app/compare_runner.hpp"
#include "app/method_registry.hpp"
#include "shared/common/error.hpp"
#include "shared/compare/compare_plan.hpp"
#include "shared/compare/results_table.hpp"
#include "shared/compare/run_hash.hpp"
#include "shared/compare/surface_error.hpp"
#include "shared/scene/scene_override.hpp"
#include "shared/solve/blas_info.hpp"

namespace altfem::cli {

namespace {

using nlohmann::json;

// Every compare run writes the embedded surface at its first and last step only and no
// volume: the surface is what the error is measured on, and frames would only add I/O time.
SceneOverride compare_output_override(const json& document) {
  json output = document.value("output", json::object());
  output["surface"] = true;
  output["volume"] = false;
  output["every"] = 1000000000;
  return {"/output", output, "output=" + output.dump()};
}

ComparePlan plan_of(const CompareArguments& arguments, const Scene& scene) {
  const std::vector<std::string> available = available_methods();
  ComparePlan plan = plan_from_scene(scene.resolved.value("compare", json()), available);
  if (!arguments.methods.empty()) plan.methods = arguments.methods;
  if (!arguments.sweeps.empty()) {
    plan.sweeps = {{}};
    for (const auto& sweep : arguments.sweeps) plan.sweeps.front().push_back(parse_sweep(sweep));
  }
  if (!arguments.reference.empty()) plan.reference = parse_reference(arguments.reference);
  for (const auto& method : plan.methods) (void)find_method(method, "--methods");  // throws naming the available ones
  if (plan.reference) (void)find_method(plan.reference->method, "--reference");
  return plan;
}

std::string text_of_file(const std::filesystem::path& file) {
  std::ifstream stream(file, std::ios::binary);
  std::ostringstream text;
  text << stream.rdbuf();
  return text.str();
}

std::string cpu_model() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  for (std::string line; std::getline(cpuinfo, line);)
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown";
}

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  return text;
}

// The hash of a configuration: of its resolved options, or, when the scene does not
// resolve with these overrides (the run will fail with exit 2), of the raw overrides.
std::string hash_of(const Configuration& configuration, const std::string& scene_text,
                    const std::filesystem::path& scene_file) {
  try {
    Scene scene = parse_scene(scene_text, scene_file, configuration.overrides);
    resolve_method_blocks(scene, {configuration.method});
    return run_hash(configuration.method, scene.resolved);
  } catch (const InputError&) {
    json invalid{{"scene", scene_text}};
    for (const auto& override_ : configuration.overrides) invalid["overrides"].push_back(override_.text);
    return run_hash(configuration.method, invalid);
  }
}

// Marks the reference and measures every successful run's surface against it.
void measure_errors(std::vector<RunRecord>& records, const std::filesystem::path& runs) {
  auto reference = std::find_if(records.begin(), records.end(), [](const RunRecord& r) { return r.is_reference; });
  if (reference == records.end() || !reference->ok()) {
    if (reference != records.end()) reference->is_reference = false;
    reference = std::max_element(records.begin(), records.end(), [](const RunRecord& a, const RunRecord& b) {
      return (a.ok() ? a.dofs : -1) < (b.ok() ? b.dofs : -1);
    });
    if (reference == records.end() || !reference->ok()) return;
    reference->is_reference = true;
  }
  const auto surface_of = [&](const RunRecord& record) {
    const json summary = json::parse(text_of_file(runs / record.hash / "summary.json"));
    return read_surface_frame(runs / record.hash / summary.at("surface").get<std::string>());
  };
  try {
    const SurfaceFrame reference_frame = surface_of(*reference);
    for (RunRecord& record : records) {
      if (!record.ok()) continue;
      try {
        const SurfaceError error = surface_error(surface_of(record), reference_frame);
        record.rms_error = error.rms;
        record.max_error = error.max;
        record.relative_rms_error = error.relative_rms;
      } catch (const std::exception& error) {
        record.message = std::string("no surface error: ") + error.what();
      }
    }
  } catch (const std::exception& error) {
    reference->message = std::string("reference surface unreadable: ") + error.what();
  }
}

}  // namespace

int compare_command(const CompareArguments& arguments) {
  if (arguments.jobs < 1) throw InputError(input_message("--jobs", "", "expected at least 1"));
  const std::filesystem::path scene_file = std::filesystem::absolute(arguments.scene);
  const Scene scene = load_scene(scene_file);
  const ComparePlan plan = plan_of(arguments, scene);
  const std::string scene_text = text_of_file(scene_file);
  const SceneOverride output_override = compare_output_override(json::parse(scene_text));

  const std::filesystem::path runs = arguments.output / "runs";
  std::filesystem::create_directories(runs);
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int threads = std::max(1, omp_get_max_threads() / arguments.jobs);
  RunRecord machine;
  machine.scene = scene.name;
  machine.date = utc_now();
  machine.cpu = cpu_model();
  machine.blas = loaded_blas().implementation;
  machine.cores = cores;
  machine.threads = threads;

  std::vector<std::string> order;  // hashes in configuration order, each once
  std::vector<PendingRun> pending;
  std::size_t reused = 0;
  for (const Configuration& configuration : expand_configurations(plan)) {
    const std::string hash = hash_of(configuration, scene_text, scene_file);
    const auto seen = std::find(order.begin(), order.end(), hash);
    if (seen != order.end()) {
      if (configuration.is_reference) {  // the reference goes last
        order.erase(seen);
        order.push_back(hash);
      }
      continue;
    }
    order.push_back(hash);
    const std::filesystem::path folder = runs / hash;
    if (!arguments.force && std::filesystem::exists(folder / "record.csv")) {
      ++reused;
      continue;
    }
    PendingRun run;
    run.folder = folder;
    run.partial = runs / (".partial-" + hash);
    run.arguments = {"run", scene_file.string(), "--method", configuration.method, "--out", run.partial.string()};
    std::string overrides;
    for (const auto& override_ : configuration.overrides) {
      run.arguments.insert(run.arguments.end(), {"--set", override_.text});
      overrides += (overrides.empty() ? "" : " ") + override_.text;
    }
    run.arguments.insert(run.arguments.end(), {"--set", output_override.text});
    run.record = machine;
    run.record.hash = hash;
    run.record.method = configuration.method;
    run.record.label = configuration.label();
    run.record.overrides = overrides;
    pending.push_back(std::move(run));
  }
  // The reference is the configuration flagged so (the last one when the plan names it).
  const std::string reference_hash = plan.reference ? order.back() : "";

  if (!run_pending(pending, arguments.jobs, threads)) {
    std::fprintf(stderr, "altfem: compare interrupted; completed runs are kept in %s, rerun to resume\n", runs.c_str());
    return 130;
  }

  std::vector<RunRecord> records;
  for (const std::string& hash : order) {
    RunRecord record = read_results_csv(runs / hash / "record.csv").at(0);
    record.is_reference = hash == reference_hash;
    if (plan.error) record.report_error = *plan.error;
    records.push_back(std::move(record));
  }
  measure_errors(records, runs);
  const std::filesystem::path results = arguments.output / "results.csv";
  write_results_csv(results, records);

  const std::string plot =
      std::string("/usr/bin/python3 '") + ALTFEM_SCRIPTS_DIR + "/plot_report.py' '" + results.string() + "'";
  const int plotted = std::system(plot.c_str());
  const long failed = std::count_if(records.begin(), records.end(), [](const RunRecord& r) { return !r.ok(); });
  std::printf("compare: %zu runs (%zu reused, %ld failed); results in %s\n", records.size(), reused, failed,
              results.c_str());
  if (plotted != 0) {
    std::fprintf(stderr, "altfem: error: the report could not be drawn (%s exited %d); results.csv is complete\n",
                 plot.c_str(), plotted);
    return exit_internal;
  }
  std::printf("compare: report in %s\n", (arguments.output / "report.md").c_str());
  return 0;
}

}  // namespace altfem::cli
