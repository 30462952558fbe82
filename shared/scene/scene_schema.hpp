#pragma once
// The scene schema as data (one rule per key of docs/scene-schema.md) and the
// validator that checks a JSON document against it and fills in the defaults.
// Methods describe their own `discretization` block with the same rules
// (method_scene_block.hpp).
#include <array>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace altfem::scene_schema {

enum class ValueType {
  number,   ///< finite, within lower/upper
  integer,  ///< a number with an integral value, within lower/upper
  boolean,
  string,             ///< one of `choices` (any non-empty string when choices is empty)
  vector3,            ///< [3] finite numbers; non-zero if `nonzero`
  integer3,           ///< [3] integers within lower/upper
  path,               ///< string; a file extension among `choices`; made absolute
  object,             ///< validated by `object`
  object_array,       ///< array of at least `minimum_count` elements, each by `object`
  components,         ///< non-empty array of distinct "x", "y", "z"
  vector3_or_string,  ///< [3] or the one string in `choices`
  expression3,        ///< [3] expressions of x, y, z, t: strings (or numbers); parsed by scene.cpp
  any,                ///< any JSON value, checked by the object's `check`
};

struct Bound {
  double value;
  bool inclusive;
};

inline constexpr Bound positive{0.0, false};
inline constexpr Bound non_negative{0.0, true};
inline constexpr Bound at_least_one{1.0, true};

struct ObjectRule;
class Validator;

struct KeyRule {
  std::string_view key;
  ValueType type;
  bool required = false;
  nlohmann::json default_value = nullptr;  ///< null: no default (the key stays absent)
  std::optional<Bound> lower = std::nullopt;
  std::optional<Bound> upper = std::nullopt;
  std::vector<std::string_view> choices = {};
  const ObjectRule* object = nullptr;
  std::size_t minimum_count = 0;
  bool nonzero = false;
};

/// A boolean key with a default.
inline KeyRule flag(std::string_view key, bool value) {
  return {.key = key, .type = ValueType::boolean, .default_value = value};
}
/// The choices of a string key from a names array (e.g. scene.hpp's).
template <std::size_t n>
std::vector<std::string_view> names(const std::array<std::string_view, n>& array) {
  return {array.begin(), array.end()};
}

/// Cross-key rules that do not fit one key: called on the resolved object.
using ObjectCheck = void (*)(const Validator& validator, const nlohmann::json& input, nlohmann::json& resolved,
                             const std::string& pointer);

struct ObjectRule {
  std::vector<KeyRule> keys;
  /// Groups of keys of which exactly one must be present.
  std::vector<std::vector<std::string_view>> exactly_one_of = {};
  /// If set, the value of this string key picks the rule for the rest of the object.
  std::string_view tag = {};
  std::vector<std::pair<std::string_view, const ObjectRule*>> variants = {};
  /// Keys beyond `keys` are kept as given, to be checked by their owner (the method
  /// blocks under `discretization`, which each method resolves).
  bool open = false;
  ObjectCheck check = nullptr;
};

/// The rule of the whole scene document.
const ObjectRule& scene_rule();

class Validator {
public:
  /// `file` names the scene in messages; relative paths resolve against `folder`.
  Validator(std::string file, std::filesystem::path folder);

  /// Checks `value` against `rule` and returns it with defaults filled and paths
  /// absolute. Throws InputError at the first problem.
  nlohmann::json resolve(const nlohmann::json& value, const ObjectRule& rule, const std::string& pointer) const;
  /// Throws InputError "file: pointer: what" (one line).
  [[noreturn]] void fail(const std::string& pointer, const std::string& what) const;

  const std::string& file() const { return file_; }

private:
  nlohmann::json resolve_value(const nlohmann::json& value, const KeyRule& rule, const std::string& pointer,
                               int depth) const;
  nlohmann::json resolve_object(const nlohmann::json& value, const ObjectRule& rule, const std::string& pointer,
                                int depth) const;
  double number(const nlohmann::json& value, const KeyRule& rule, const std::string& pointer) const;

  std::string file_;
  std::filesystem::path folder_;
};

/// "got …" text for a JSON value: numbers and short strings verbatim, else its type.
std::string describe(const nlohmann::json& value);
/// The closest of `candidates` to `word` within edit distance length/3 (1 to 3), if any.
std::optional<std::string_view> closest(std::string_view word, const std::vector<std::string_view>& candidates);
/// Escapes '~' and '/' for a JSON pointer token (RFC 6901).
std::string pointer_token(std::string_view key);

}  // namespace altfem::scene_schema
