#include <chrono>
#include <cstdio>

#include "app/commands.hpp"
#include "app/method_registry.hpp"
#include "shared/io/output_folder.hpp"
#include "shared/scene/scene.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/scene/scene_override.hpp"
#include "shared/simulation/run_simulation.hpp"
#include "shared/solve/process_ranks.hpp"

namespace altfem::cli {

int run_command(const std::filesystem::path& scene_file, const std::string& method,
                const std::filesystem::path& output_directory, const std::vector<std::string>& overrides) {
  const auto start = std::chrono::steady_clock::now();
  const MethodDescription& description = find_method(method);
  std::vector<SceneOverride> assignments;
  for (const auto& assignment : overrides) assignments.push_back(parse_scene_override(assignment));
  Scene scene = load_scene(scene_file, assignments);
  resolve_method_blocks(scene, {method});
  const SceneGeometry geometry = load_scene_geometry(scene);
  for (const auto& warning : geometry.warnings) std::fprintf(stderr, "altfem: warning: %s\n", warning.c_str());
  const std::filesystem::path out =
      output_directory.empty() ? std::filesystem::path("out") / (scene.name + "-" + method) : output_directory;
  check_output_folder(out);  // before any work: a bad --out is bad input (exit 2), not an internal error
  const double loading = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const nlohmann::json summary = run_simulation(scene, geometry, method, description, out, loading);
  if (ranks::index() != 0) return 0;
  std::printf("%s with %s: %lld DOFs, %d steps, %lld Newton iterations, %.3f s; results in %s\n", scene.name.c_str(),
              method.c_str(), summary["dofs"].get<long long>(), summary["steps"].get<int>(),
              summary["newton_iterations"].get<long long>(), summary["timings_s"]["total"].get<double>(), out.c_str());
  return 0;
}

}  // namespace altfem::cli
