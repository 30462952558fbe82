#include <cstdio>
#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "shared/scene/scene.hpp"
#include "shared/scene/scene_geometry.hpp"

namespace altfem::cli {

namespace {

nlohmann::json geometry_facts(const SceneGeometry& geometry) {
  nlohmann::json facts;
  if (geometry.surface) {
    facts["kind"] = "surface";
    facts["vertices"] = geometry.surface->vertices.rows();
    facts["faces"] = geometry.surface->triangles.rows();
  } else if (geometry.mesh) {
    facts["kind"] = "mesh";
    facts["element"] = std::string(element_name(geometry.mesh->element_type));
    facts["vertices"] = geometry.mesh->nodes.rows();
    facts["cells"] = geometry.mesh->cells.rows();
  } else {
    facts["kind"] = "shape";
  }
  const auto& box = geometry.bounds;
  facts["bounding_box"] = {{"min", {box.min().x(), box.min().y(), box.min().z()}},
                           {"max", {box.max().x(), box.max().y(), box.max().z()}}};
  facts["volume"] = geometry.volume;
  facts["closed"] = geometry.closed;
  facts["manifold"] = geometry.manifold;
  facts["warnings"] = geometry.warnings;
  return facts;
}

}  // namespace

int check_command(const std::filesystem::path& scene_file, bool json) {
  const Scene scene = load_scene(scene_file);
  const SceneGeometry geometry = load_scene_geometry(scene);
  for (const auto& warning : geometry.warnings) std::fprintf(stderr, "altfem: warning: %s\n", warning.c_str());
  const nlohmann::json facts = geometry_facts(geometry);
  if (json) {
    std::printf("%s\n", nlohmann::json{{"scene", scene.resolved}, {"geometry", facts}}.dump(2).c_str());
    return 0;
  }
  std::printf("%s: valid scene '%s'\n", scene_file.c_str(), scene.name.c_str());
  std::printf("%s\n", scene.resolved.dump(2).c_str());
  std::printf("geometry: %s", facts["kind"].get<std::string>().c_str());
  if (facts.contains("faces"))
    std::printf(", %lld vertices, %lld faces", facts["vertices"].get<long long>(), facts["faces"].get<long long>());
  if (facts.contains("cells"))
    std::printf(", %s, %lld vertices, %lld cells", facts["element"].get<std::string>().c_str(),
                facts["vertices"].get<long long>(), facts["cells"].get<long long>());
  const auto& box = geometry.bounds;
  std::printf("\nbounding box: [%g, %g, %g] – [%g, %g, %g]\nvolume: %.6g\nclosed: %s, manifold: %s\n", box.min().x(),
              box.min().y(), box.min().z(), box.max().x(), box.max().y(), box.max().z(), geometry.volume,
              geometry.closed ? "yes" : "no", geometry.manifold ? "yes" : "no");
  return 0;
}

}  // namespace altfem::cli
