// The generic half of the scene validator: walks a JSON document along the rules
// of scene_schema.cpp. Nothing here knows a particular key.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>

#include "shared/common/error.hpp"
#include "shared/scene/scene_schema.hpp"

namespace altfem::scene_schema {

namespace {

using nlohmann::json;

// Guards the recursion of nested CSG shapes against hostile input.
constexpr int maximum_depth = 64;

std::string quoted(std::string_view text) {
  std::string result(1, '\'');  // appended, not "'" + …: GCC 12 warns falsely (-Wrestrict) on that
  result.append(text);
  result.push_back('\'');
  return result;
}

std::string choice_list(const std::vector<std::string_view>& choices) {
  std::string list;
  for (const auto& choice : choices) list += (list.empty() ? "" : ", ") + quoted(choice);
  return list;
}

std::string format_number(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char text[32];
  if (value == std::floor(value) && std::abs(value) < 1e15) {
    std::snprintf(text, sizeof text, "%.0f", value);
    return text;
  }
  // The shortest %g form that reads back exactly: 0.5, 1e-05.
  for (int precision = 1; precision <= 17; ++precision) {
    std::snprintf(text, sizeof text, "%.*g", precision, value);
    if (std::strtod(text, nullptr) == value) break;
  }
  return text;
}

std::string bound_text(const Bound& bound, bool lower) {
  return std::string(lower ? (bound.inclusive ? ">= " : "> ") : (bound.inclusive ? "<= " : "< ")) +
         format_number(bound.value);
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::vector<std::string_view> key_names(const ObjectRule& rule) {
  std::vector<std::string_view> names;
  for (const auto& key : rule.keys) names.push_back(key.key);
  if (!rule.tag.empty()) names.push_back(rule.tag);
  return names;
}

const KeyRule* find_key(const ObjectRule& rule, std::string_view key) {
  for (const auto& candidate : rule.keys)
    if (candidate.key == key) return &candidate;
  return nullptr;
}

}  // namespace

std::string describe(const json& value) {
  switch (value.type()) {
    case json::value_t::null: return "null";
    case json::value_t::boolean: return value.get<bool>() ? "true" : "false";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned: return value.dump();
    case json::value_t::number_float: return format_number(value.get<double>());
    case json::value_t::string: {
      const auto& text = value.get_ref<const std::string&>();
      if (text.size() > 120) return json(text.substr(0, 117)).dump() + "...";
      return json(text).dump();  // quoted and escaped, so always one line
    }
    case json::value_t::array: return "an array of " + std::to_string(value.size()) + " elements";
    case json::value_t::object: return "an object";
    default: return "a binary value";
  }
}

std::optional<std::string_view> closest(std::string_view word, const std::vector<std::string_view>& candidates) {
  // A short word is close only to a near-identical key ("colour" is not "solver").
  std::optional<std::string_view> best;
  std::size_t best_distance = std::clamp<std::size_t>(word.size() / 3, 1, 3) + 1;
  for (const auto& candidate : candidates) {
    const std::size_t distance = edit_distance(word, candidate);
    if (distance < best_distance) best_distance = distance, best = candidate;
  }
  return best;
}

std::string pointer_token(std::string_view key) {
  std::string token;
  for (char c : key) {
    if (c == '~') token += "~0";
    else if (c == '/') token += "~1";
    else token += c;
  }
  return token;
}

Validator::Validator(std::string file, std::filesystem::path folder)
    : file_(std::move(file)), folder_(std::move(folder)) {}

void Validator::fail(const std::string& pointer, const std::string& what) const {
  std::string message = input_message(file_, pointer.empty() ? "/" : pointer, what);
  std::replace_if(
      message.begin(), message.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
  throw InputError(message);
}

json Validator::resolve(const json& value, const ObjectRule& rule, const std::string& pointer) const {
  return resolve_object(value, rule, pointer, 0);
}

double Validator::number(const json& value, const KeyRule& rule, const std::string& pointer) const {
  const bool integral = rule.type == ValueType::integer || rule.type == ValueType::integer3;
  if (!value.is_number())
    fail(pointer, std::string("expected ") + (integral ? "an integer" : "a number") + ", got " + describe(value));
  const double x = value.get<double>();
  if (!std::isfinite(x)) fail(pointer, "expected a finite number, got " + describe(value));
  if (integral && (x != std::floor(x) || std::abs(x) > 1e9))
    fail(pointer, "expected an integer, got " + describe(value));
  if (rule.lower && (x < rule.lower->value || (!rule.lower->inclusive && x == rule.lower->value)))
    fail(pointer, "must be " + bound_text(*rule.lower, true) + ", got " + describe(value));
  if (rule.upper && (x > rule.upper->value || (!rule.upper->inclusive && x == rule.upper->value)))
    fail(pointer, "must be " + bound_text(*rule.upper, false) + ", got " + describe(value));
  return x;
}

json Validator::resolve_value(const json& value, const KeyRule& rule, const std::string& pointer, int depth) const {
  switch (rule.type) {
    case ValueType::number: return number(value, rule, pointer);
    case ValueType::integer: return static_cast<long long>(number(value, rule, pointer));
    case ValueType::boolean:
      if (!value.is_boolean()) fail(pointer, "expected true or false, got " + describe(value));
      return value;
    case ValueType::string: {
      if (!value.is_string()) fail(pointer, "expected a string, got " + describe(value));
      const auto& text = value.get_ref<const std::string&>();
      if (rule.choices.empty()) {
        if (text.empty()) fail(pointer, "expected a non-empty string, got \"\"");
        return value;
      }
      if (std::find(rule.choices.begin(), rule.choices.end(), text) == rule.choices.end()) {
        std::string what = "expected one of " + choice_list(rule.choices) + ", got " + describe(value);
        if (const auto hint = closest(text, rule.choices)) what += "; did you mean " + quoted(*hint) + "?";
        fail(pointer, what);
      }
      return value;
    }
    case ValueType::vector3:
    case ValueType::integer3: {
      const bool integral = rule.type == ValueType::integer3;
      const std::string expected = integral ? "an array of 3 integers" : "an array of 3 numbers";
      if (!value.is_array() || value.size() != 3) fail(pointer, "expected " + expected + ", got " + describe(value));
      json result = json::array();
      double norm = 0.0;
      for (std::size_t i = 0; i < 3; ++i) {
        const KeyRule element{.key = rule.key,
                              .type = integral ? ValueType::integer : ValueType::number,
                              .lower = rule.lower,
                              .upper = rule.upper};
        const double x = number(value[i], element, pointer + "/" + std::to_string(i));
        norm += x * x;
        if (integral) result.push_back(static_cast<long long>(x));
        else result.push_back(x);
      }
      if (rule.nonzero && !(norm > 0.0)) fail(pointer, "expected a non-zero vector, got [0, 0, 0]");
      return result;
    }
    case ValueType::path: {
      if (!value.is_string() || value.get_ref<const std::string&>().empty())
        fail(pointer, "expected a file path, got " + describe(value));
      const std::filesystem::path path(value.get<std::string>());
      std::string extension = path.extension().string();
      std::transform(extension.begin(), extension.end(), extension.begin(),
                     [](unsigned char c) { return std::tolower(c); });
      if (std::find(rule.choices.begin(), rule.choices.end(), extension) == rule.choices.end())
        fail(pointer, "expected a file ending in one of " + choice_list(rule.choices) + ", got " + describe(value));
      return (path.is_absolute() ? path : folder_ / path).lexically_normal().string();
    }
    case ValueType::object: return resolve_object(value, *rule.object, pointer, depth + 1);
    case ValueType::any: return value;
    case ValueType::object_array: {
      if (!value.is_array()) fail(pointer, "expected an array, got " + describe(value));
      if (value.size() < rule.minimum_count)
        fail(pointer, "expected an array of at least " + std::to_string(rule.minimum_count) + " elements, got " +
                          describe(value));
      json result = json::array();
      for (std::size_t i = 0; i < value.size(); ++i)
        result.push_back(resolve_object(value[i], *rule.object, pointer + "/" + std::to_string(i), depth + 1));
      return result;
    }
    case ValueType::components: {
      if (!value.is_array() || value.empty() || value.size() > 3)
        fail(pointer, "expected a non-empty array of \"x\", \"y\", \"z\", got " + describe(value));
      std::set<std::string> seen;
      for (std::size_t i = 0; i < value.size(); ++i) {
        const json& item = value[i];
        if (!item.is_string() || (item != "x" && item != "y" && item != "z") ||
            !seen.insert(item.get<std::string>()).second)
          fail(pointer + "/" + std::to_string(i),
               "expected a distinct one of \"x\", \"y\", \"z\", got " + describe(item));
      }
      return value;
    }
    case ValueType::expression3: {
      if (!value.is_array() || value.size() != 3)
        fail(pointer, "expected an array of 3 expressions of x, y, z, t (strings), got " + describe(value));
      for (std::size_t i = 0; i < 3; ++i)
        if (!value[i].is_string() && !value[i].is_number())
          fail(pointer + "/" + std::to_string(i),
               "expected an expression of x, y, z, t (a string), got " + describe(value[i]));
      for (std::size_t i = 0; i < 3; ++i)
        if (value[i].is_number())
          number(value[i], KeyRule{.key = rule.key, .type = ValueType::number}, pointer + "/" + std::to_string(i));
      return value;
    }
    case ValueType::vector3_or_string:
      if (value.is_string()) {
        if (value != rule.choices.front())
          fail(pointer, "expected an array of 3 numbers or \"" + std::string(rule.choices.front()) + "\", got " +
                            describe(value));
        return value;
      }
      return resolve_value(value, KeyRule{.key = rule.key, .type = ValueType::vector3}, pointer, depth);
  }
  return value;
}

json Validator::resolve_object(const json& value, const ObjectRule& given_rule, const std::string& pointer,
                               int depth) const {
  if (depth > maximum_depth)
    fail(pointer, "expected nesting at most " + std::to_string(maximum_depth) + " deep, got deeper");
  if (!value.is_object()) fail(pointer, "expected an object, got " + describe(value));
  const ObjectRule* rule = &given_rule;
  json resolved = json::object();
  if (!rule->tag.empty()) {
    const std::string tag_pointer = pointer + "/" + pointer_token(rule->tag);
    std::vector<std::string_view> names;
    for (const auto& [name, variant] : rule->variants) names.push_back(name);
    if (!value.contains(rule->tag))
      fail(pointer, "missing required key '" + std::string(rule->tag) + "' (one of " + choice_list(names) + ")");
    const json& tag = value.at(std::string(rule->tag));
    resolve_value(tag, KeyRule{.key = rule->tag, .type = ValueType::string, .choices = names}, tag_pointer, depth);
    for (const auto& [name, variant] : rule->variants)
      if (tag == name) rule = variant;
    resolved[std::string(given_rule.tag)] = tag;
  }

  for (const auto& [key, item] : value.items()) {
    if (!given_rule.tag.empty() && key == given_rule.tag) continue;
    const std::string key_pointer = pointer + "/" + pointer_token(key);
    if (find_key(*rule, key)) continue;
    if (rule->open) {
      resolved[key] = item;
      continue;
    }
    std::string what = "unknown key";
    if (!given_rule.tag.empty())
      what += " for " + std::string(given_rule.tag) + " " + describe(resolved[std::string(given_rule.tag)]);
    what += ", expected one of " + choice_list(key_names(*rule));
    if (const auto hint = closest(key, key_names(*rule))) what += "; did you mean " + quoted(*hint) + "?";
    fail(key_pointer, what);
  }

  for (const auto& group : rule->exactly_one_of) {
    const auto count =
        std::count_if(group.begin(), group.end(), [&](std::string_view key) { return value.contains(key); });
    if (count != 1) fail(pointer, "expected exactly one of " + choice_list(group) + ", got " + std::to_string(count));
  }

  for (const auto& key : rule->keys) {
    const std::string name(key.key);
    const std::string key_pointer = pointer + "/" + pointer_token(name);
    if (value.contains(name)) resolved[name] = resolve_value(value.at(name), key, key_pointer, depth);
    else if (!key.default_value.is_null()) resolved[name] = resolve_value(key.default_value, key, key_pointer, depth);
    else if (key.required) fail(key_pointer, "missing required key '" + name + "'");
  }
  if (rule->check) rule->check(*this, value, resolved, pointer);
  return resolved;
}

}  // namespace altfem::scene_schema
