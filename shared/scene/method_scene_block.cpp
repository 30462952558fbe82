#include "shared/scene/method_scene_block.hpp"

#include <algorithm>
#include <vector>

#include "shared/common/error.hpp"

namespace altfem {

namespace {

scene_schema::Validator validator_of(const Scene& scene) {
  const std::filesystem::path& file = scene.file;
  // Relative paths in a block resolve against the scene's folder, as in parse_scene.
  const std::filesystem::path folder =
      file.has_parent_path() ? std::filesystem::absolute(file).parent_path() : std::filesystem::current_path();
  return scene_schema::Validator(file.string(), folder);
}

}  // namespace

nlohmann::json resolve_method_block(const Scene& scene, const MethodSceneBlock& block) {
  const std::string name(block.name);
  const nlohmann::json& blocks = scene.resolved.at("discretization");
  const nlohmann::json given = blocks.contains(name) ? blocks[name] : nlohmann::json::object();
  const std::string pointer = "/discretization/" + scene_schema::pointer_token(name);
  const scene_schema::Validator validator = validator_of(scene);
  nlohmann::json resolved = validator.resolve(given, *block.rule, pointer);
  if (block.complete) block.complete(validator, scene.resolved, resolved, pointer);
  return resolved;
}

void check_method_block_names(const Scene& scene, std::span<const MethodSceneBlock> blocks) {
  std::vector<std::string_view> names;
  for (const auto& block : blocks) names.push_back(block.name);
  for (const auto& [name, value] : scene.resolved.at("discretization").items()) {
    if (std::find(names.begin(), names.end(), name) != names.end()) continue;
    std::string list;
    for (const auto& known : names) list += (list.empty() ? "'" : ", '") + std::string(known) + "'";
    std::string what = "method '" + name + "' is not available in this build (available: " + list + ")";
    if (const auto hint = scene_schema::closest(name, names)) what += "; did you mean '" + std::string(*hint) + "'?";
    validator_of(scene).fail("/discretization/" + scene_schema::pointer_token(name), what);
  }
}

}  // namespace altfem
