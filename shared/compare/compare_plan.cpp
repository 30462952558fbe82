#include "shared/compare/compare_plan.hpp"

#include <algorithm>

#include "shared/common/error.hpp"

namespace altfem {

using nlohmann::json;

namespace {

// The method a pointer belongs to ("/discretization/fem/..." → "fem"), or "" for a scene-wide key.
std::string method_of_pointer(const std::string& pointer) {
  const std::string prefix = "/discretization/";
  if (pointer.rfind(prefix, 0) != 0) return "";
  const auto end = pointer.find('/', prefix.size());
  return pointer.substr(prefix.size(), end == std::string::npos ? std::string::npos : end - prefix.size());
}

SceneOverride make_override(const std::string& pointer, const json& value) {
  const std::string shown = value.is_string() ? value.get<std::string>() : value.dump();
  return {pointer, value, pointer.substr(1) + "=" + shown};
}

// Values longer than this are named by their leaves in labels.
constexpr std::size_t longest_shown_value = 24;

std::string shown(const json& value) { return value.is_string() ? value.get<std::string>() : value.dump(); }

// The last token of a flattened pointer that is not an array index ("/0/refine/cycles" → "cycles").
std::string leaf_name(const std::string& pointer) {
  std::string name;
  std::size_t end = pointer.size();
  while (end > 0) {
    const std::size_t slash = pointer.rfind('/', end - 1);
    name = pointer.substr(slash + 1, end - slash - 1);
    if (!name.empty() && name.find_first_not_of("0123456789") != std::string::npos) return name;
    end = slash;
  }
  return name;
}

// A long value as "name=value,…" over the leaves in which it differs from its siblings (the
// other values of its sweep), or over all its leaves when none differ: refinement events
// read "cycles=4", not their whole JSON. "" for a value short enough to show whole.
std::string value_label(const json& value, const std::vector<json>& siblings) {
  if (!value.is_structured() || shown(value).size() <= longest_shown_value) return "";
  const json leaves = value.flatten();
  std::vector<json> others;
  for (const json& sibling : siblings) others.push_back(sibling.is_structured() ? sibling.flatten() : json::object());
  std::vector<std::string> differing;
  for (const auto& [pointer, leaf] : leaves.items())
    if (std::any_of(others.begin(), others.end(),
                    [&](const json& other) { return !other.contains(pointer) || other[pointer] != leaf; }))
      differing.push_back(pointer);
  if (differing.empty())
    for (const auto& [pointer, leaf] : leaves.items()) differing.push_back(pointer);
  std::string text;
  for (const std::string& pointer : differing)
    text += (text.empty() ? "" : ",") + leaf_name(pointer) + "=" + shown(leaves[pointer]);
  return text;
}

}  // namespace

std::string Configuration::label() const {
  std::string text = method;
  for (std::size_t k = 0; k < overrides.size(); ++k) {
    const SceneOverride& override_ = overrides[k];
    const std::string key = override_.pointer.substr(override_.pointer.rfind('/') + 1);
    const std::string named = k < value_labels.size() ? value_labels[k] : "";
    text += " " + (named.empty() ? key + "=" + shown(override_.value) : key + "(" + named + ")");
  }
  return text;
}

std::vector<std::string> split_top_level(std::string_view text, char separator) {
  std::vector<std::string> parts(1);
  int depth = 0;
  bool quoted = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '\\' && i + 1 < text.size()) parts.back() += text[i++];
      else if (c == '"') quoted = false;
    } else if (c == '"') {
      quoted = true;
    } else if (c == '[' || c == '{') {
      ++depth;
    } else if (c == ']' || c == '}') {
      --depth;
    } else if (c == separator && depth == 0) {
      parts.emplace_back();
      continue;
    }
    parts.back() += c;
  }
  return parts;
}

Sweep parse_sweep(std::string_view text) {
  const SceneOverride whole = parse_scene_override(text, "--sweep");
  const std::string values_text(text.substr(text.find('=') + 1));
  Sweep sweep{whole.pointer, {}};
  for (const std::string& part : split_top_level(values_text, ',')) {
    if (part.empty())
      throw InputError(input_message("--sweep", std::string(text), "expected KEY=V1,V2,... with no empty value"));
    sweep.values.push_back(parse_scene_override("x=" + part, "--sweep").value);
  }
  return sweep;
}

ReferenceSpec parse_reference(std::string_view text) {
  const auto colon = text.find(':');
  ReferenceSpec reference{std::string(text.substr(0, colon)), {}};
  if (reference.method.empty())
    throw InputError(input_message("--reference", std::string(text), "expected METHOD[:KEY=VALUE,...]"));
  if (colon == std::string_view::npos) return reference;
  for (const std::string& part : split_top_level(text.substr(colon + 1), ','))
    reference.overrides.push_back(parse_scene_override(part, "--reference"));
  return reference;
}

ComparePlan plan_from_scene(const json& compare_block, const std::vector<std::string>& available_methods) {
  ComparePlan plan;
  const bool present = compare_block.is_object();
  if (present && compare_block.contains("methods"))
    for (const auto& name : compare_block["methods"]) plan.methods.push_back(name.get<std::string>());
  else plan.methods = available_methods;
  if (present && compare_block.contains("sweeps")) {
    const json& sweeps = compare_block["sweeps"];
    for (const json& group : sweeps.is_array() ? sweeps : json::array({sweeps})) {
      SweepGroup& swept = plan.sweeps.emplace_back();
      for (const auto& [key, values] : group.items()) {
        Sweep sweep{key.front() == '/' ? key : "/" + key, {}};
        for (const auto& value : values) sweep.values.push_back(value);
        swept.push_back(std::move(sweep));
      }
    }
  }
  if (present && compare_block.contains("error")) plan.error = compare_block["error"].get<double>();
  if (present && compare_block.contains("reference")) {
    const json& reference = compare_block["reference"];
    ReferenceSpec spec{reference["method"].get<std::string>(), {}};
    for (const auto& [key, value] : reference["set"].items())
      spec.overrides.push_back(make_override(key.front() == '/' ? key : "/" + key, value));
    plan.reference = std::move(spec);
  }
  return plan;
}

std::vector<Configuration> expand_configurations(const ComparePlan& plan) {
  std::vector<Configuration> configurations;
  const std::vector<SweepGroup> groups = plan.sweeps.empty() ? std::vector<SweepGroup>{{}} : plan.sweeps;
  for (const std::string& method : plan.methods) {
    for (const SweepGroup& group : groups) {
      std::vector<const Sweep*> applicable;
      for (const Sweep& sweep : group) {
        const std::string owner = method_of_pointer(sweep.pointer);
        if (owner.empty() || owner == method) applicable.push_back(&sweep);
      }
      // An odometer over the applicable sweeps; the last one varies fastest.
      std::vector<std::size_t> index(applicable.size(), 0);
      while (true) {
        Configuration configuration{method, {}, false, {}};
        for (std::size_t k = 0; k < applicable.size(); ++k) {
          const json& value = applicable[k]->values[index[k]];
          configuration.overrides.push_back(make_override(applicable[k]->pointer, value));
          configuration.value_labels.push_back(value_label(value, applicable[k]->values));
        }
        configurations.push_back(std::move(configuration));
        std::size_t k = applicable.size();
        while (k > 0 && ++index[k - 1] == applicable[k - 1]->values.size()) index[--k] = 0;
        if (k == 0) break;
      }
    }
  }
  if (plan.reference) {
    Configuration reference{plan.reference->method, plan.reference->overrides, true, {}};
    for (const SceneOverride& override_ : reference.overrides)
      reference.value_labels.push_back(value_label(override_.value, {}));
    configurations.push_back(std::move(reference));
  }
  return configurations;
}

}  // namespace altfem
