#include "shared/scene/scene_override.hpp"

#include "shared/common/error.hpp"

namespace altfem {

using nlohmann::json;

SceneOverride parse_scene_override(std::string_view assignment, const std::string& option) {
  const std::string text(assignment);
  const auto equals = assignment.find('=');
  if (equals == std::string_view::npos)
    throw InputError(input_message(option, "", "expected KEY=VALUE (KEY a JSON pointer), got " + json(text).dump()));
  std::string pointer(assignment.substr(0, equals));
  if (!pointer.empty() && pointer.front() != '/') pointer.insert(pointer.begin(), '/');
  if (pointer.empty() || pointer == "/")
    throw InputError(input_message(option, text, "expected a JSON pointer before '=', got an empty key"));
  try {
    (void)json::json_pointer(pointer);
  } catch (const json::exception&) {
    throw InputError(input_message(
        option, text, "expected a JSON pointer (RFC 6901; '~' only as ~0 or ~1), got " + json(pointer).dump()));
  }
  const std::string value_text(assignment.substr(equals + 1));
  // A value that is not JSON is a string, so `element=tet4` needs no quotes.
  json value = json::parse(value_text, nullptr, /*allow_exceptions=*/false);
  if (value.is_discarded()) value = value_text;
  return {pointer, std::move(value), text};
}

void apply_scene_overrides(json& document, const std::vector<SceneOverride>& overrides, const std::string& file) {
  for (const SceneOverride& override_ : overrides) {
    const std::string where = "--set " + override_.text;
    // Walk the pointer's tokens; missing objects on the way are created (the validator
    // then names an unknown key, with a "did you mean" hint for a typo).
    std::vector<std::string> tokens;
    for (json::json_pointer rest(override_.pointer); !rest.empty(); rest.pop_back())
      tokens.insert(tokens.begin(), rest.back());
    json* node = &document;
    std::string walked;
    for (std::size_t k = 0; k < tokens.size(); ++k) {
      const std::string& token = tokens[k];
      const bool last = k + 1 == tokens.size();
      if (node->is_null()) *node = json::object();
      if (node->is_object()) {
        node = &(*node)[token];
      } else if (node->is_array()) {
        const bool digits = !token.empty() && token.find_first_not_of("0123456789") == std::string::npos;
        if (last && token == "-") {
          node->push_back(nullptr);
          node = &node->back();
        } else if (digits && std::stoull(token) < node->size()) {
          node = &(*node)[std::stoull(token)];
        } else {
          throw InputError(input_message(file, where,
                                         "expected an index below " + std::to_string(node->size()) +
                                             (last ? " or '-'" : "") + " into " + (walked.empty() ? "/" : walked) +
                                             ", got '" + token + "'"));
        }
      } else {
        throw InputError(input_message(
            file, where, (walked.empty() ? "/" : walked) + " is a " + node->type_name() + ", not an object or array"));
      }
      walked += "/" + token;
    }
    *node = override_.value;
  }
}

}  // namespace altfem
