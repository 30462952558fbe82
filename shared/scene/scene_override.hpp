#pragma once
// `--set KEY=VALUE`: a JSON-pointer assignment into a scene document before it is
// validated (docs/scene-schema.md, "Overrides"). `altfem run` and `altfem compare`
// share it, so a compare configuration is exactly a run with some overrides.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "shared/scene/scene.hpp"

namespace altfem {

struct SceneOverride {
  std::string pointer;   ///< RFC 6901, always with the leading '/', e.g. "/discretization/fem/resolution"
  nlohmann::json value;  ///< the VALUE parsed as JSON, or the text itself as a string
  std::string text;      ///< the assignment as written, for messages and labels
};

/// Parses "KEY=VALUE": KEY is a JSON pointer with or without its leading '/', VALUE is
/// JSON (`[8,2,2]`, `0.3`, `true`, `"tet4"`) or else taken as a string (`tet4`).
/// Throws InputError naming `option` for a missing '=', an empty key or a malformed pointer.
SceneOverride parse_scene_override(std::string_view assignment, const std::string& option = "--set");

/// Assigns every override, in order, into `document`. Missing objects along the
/// pointer are created; an array index must be in range (or '-' to append as the last
/// token). Throws InputError "file: --set KEY=VALUE: what" when a step is a scalar or a bad index.
void apply_scene_overrides(nlohmann::json& document, const std::vector<SceneOverride>& overrides,
                           const std::string& file);

/// load_scene with `overrides` applied to the parsed document before validation.
Scene load_scene(const std::filesystem::path& path, const std::vector<SceneOverride>& overrides);
/// parse_scene with `overrides` applied to the parsed document before validation.
Scene parse_scene(std::string_view text, const std::filesystem::path& file,
                  const std::vector<SceneOverride>& overrides);

}  // namespace altfem
