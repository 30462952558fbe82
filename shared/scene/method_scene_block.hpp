#pragma once
// A method's part of the scene: its block under /discretization. Each method
// describes its block with the schema's rules (scene_schema.hpp) and resolves it
// itself, so adding a method edits no file of shared/scene (docs/scene-schema.md,
// "Discretization").
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <string_view>

#include "shared/scene/scene.hpp"
#include "shared/scene/scene_schema.hpp"

namespace altfem {

struct MethodSceneBlock {
  std::string_view name;                 ///< the key under /discretization and the --method name
  const scene_schema::ObjectRule* rule;  ///< the block's keys, their defaults and ranges
  /// Defaults that depend on the rest of the scene (its geometry) and checks across
  /// keys: called with the resolved scene and the block already resolved by `rule`;
  /// may be null.
  void (*complete)(const scene_schema::Validator& validator, const nlohmann::json& scene, nlohmann::json& block,
                   const std::string& pointer) = nullptr;
};

/// The block /discretization/<name> of `scene`, validated and with its defaults filled
/// (an absent block is `{}`). Idempotent: resolving a resolved block gives it back.
/// Throws InputError naming the scene file and the key.
nlohmann::json resolve_method_block(const Scene& scene, const MethodSceneBlock& block);

/// Rejects a block under /discretization whose name is none of `blocks` (a method not
/// in this build, or a typo), with a "did you mean".
void check_method_block_names(const Scene& scene, std::span<const MethodSceneBlock> blocks);

}  // namespace altfem
