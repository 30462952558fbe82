// `altfem mesh`: builds a method's mesh without solving, writes it as VTU and prints its
// facts, so users look at a mesh before they pay for a run. Each method builds its own
// preview (MethodDescription::mesh_preview); this file names none.
#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "app/method_registry.hpp"
#include "shared/common/error.hpp"
#include "shared/io/vtu_writer.hpp"
#include "shared/scene/scene.hpp"
#include "shared/scene/scene_geometry.hpp"

namespace altfem::cli {

namespace {

// The command line's source and slicing options, checked with messages naming the flags.
MeshPreviewOptions preview_options(const MeshCommandOptions& options) {
  if (options.resolution < 1) throw InputError("--resolution: must be >= 1, got " + std::to_string(options.resolution));
  if (!(options.sliver_fraction >= 0 && options.sliver_fraction < 1))
    throw InputError("--sliver-fraction: must be in [0, 1), got " + std::to_string(options.sliver_fraction));
  if (options.octree_levels < 0 || options.octree_levels > 10)
    throw InputError("--octree-levels: must be in 0..10, got " + std::to_string(options.octree_levels));
  MeshPreviewOptions preview;
  preview.source = options.source;
  preview.slicing.resolution = options.resolution;
  preview.slicing.sliver_fraction = options.sliver_fraction;
  preview.slicing.octree_levels = options.octree_levels;
  return preview;
}

}  // namespace

int mesh_command(const std::filesystem::path& scene_file, const MeshCommandOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const MethodDescription& method = find_method(options.method);
  if (!method.mesh_preview) throw InputError("--method " + options.method + ": this method has no mesh preview");
  const MeshPreviewOptions preview_choice = preview_options(options);
  Scene scene = load_scene(scene_file);
  resolve_method_blocks(scene, {options.method});
  const SceneGeometry geometry = load_scene_geometry(scene);
  for (const auto& warning : geometry.warnings) std::fprintf(stderr, "altfem: warning: %s\n", warning.c_str());
  MeshPreview preview = method.mesh_preview(scene, geometry, preview_choice);
  for (const auto& warning : preview.warnings) std::fprintf(stderr, "altfem: warning: %s\n", warning.c_str());
  const double build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // --out DIR writes DIR/mesh.vtu; --out FILE.vtu writes that file.
  const std::filesystem::path out = options.output_directory.empty()
                                        ? std::filesystem::path("out") / (scene.name + "-mesh-" + options.method)
                                        : options.output_directory;
  const std::filesystem::path vtu = out.extension() == ".vtu" ? out : out / "mesh.vtu";
  if (!vtu.parent_path().empty()) std::filesystem::create_directories(vtu.parent_path());
  write_vtu(vtu, preview.grid);

  nlohmann::json& facts = preview.facts;
  facts["method"] = options.method;
  facts["build_time_s"] = build_seconds;
  facts["file"] = vtu.string();
  if (options.json) {
    std::printf("%s\n", facts.dump(2).c_str());
    return 0;
  }
  std::printf("%sbuild time: %.3f s\nwritten: %s\n", preview.summary.c_str(), build_seconds, vtu.c_str());
  return 0;
}

}  // namespace altfem::cli
