// docs/scene-schema.md and the schema rules say the same thing, key path by key path:
// every key of every rule (shared/scene's and each registered method's block) has a row
// in the document under its full path, and every row names a path some rule has. Rules
// documented in a section of their own (shapes, regions, motions, slicing) are checked
// there with paths relative to the rule; where another rule reaches them, only the key
// that holds them needs a row.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "app/method_registry.hpp"
#include "shared/scene/scene_schema.hpp"
#include "shared/scene/scene_slicing.hpp"

namespace altfem {
namespace {

using scene_schema::ObjectRule;
using scene_schema::ValueType;

// The object rule of the key `key` of `rule` (nullptr when it has none).
const ObjectRule* object_of(const ObjectRule& rule, std::string_view key) {
  for (const auto& entry : rule.keys)
    if (entry.key == key) return entry.object;
  return nullptr;
}

// A rule documented in a section of its own, its rows relative to it after `prefix`.
struct TypeSection {
  std::string heading;  // the section's heading, after the #s
  const ObjectRule* rule;
  std::string prefix;
};

std::vector<TypeSection> type_sections() {
  const ObjectRule& scene = scene_schema::scene_rule();
  const ObjectRule* conditions = object_of(scene, "boundary_conditions");
  return {{"Analytic shapes", object_of(*object_of(scene, "geometry"), "shape"), ""},
          {"Regions", object_of(*conditions, "region"), ""},
          {"Motions", object_of(*conditions, "motion"), ""},
          {"Slicing", &slicing_rule(), "slice/"}};
}

// The paths of a rule: `required` are the keys that need a row (values, the tag and its
// variants, keys holding a rule documented elsewhere), `containers` the objects and
// arrays whose keys have rows of their own (a row for them is allowed, not needed).
struct RulePaths {
  std::set<std::string> required, containers;
};

class PathWalker {
public:
  explicit PathWalker(std::set<const ObjectRule*> documented_elsewhere)
      : documented_elsewhere_(std::move(documented_elsewhere)) {}

  void walk(const ObjectRule& rule, const std::string& prefix, RulePaths& paths) const {
    if (!rule.tag.empty()) paths.required.insert(prefix + "/" + std::string(rule.tag));
    for (const auto& [name, variant] : rule.variants) {
      // A variant with keys is documented by its keys' rows ("translate/velocity").
      const std::string path = prefix + "/" + std::string(name);
      (variant->keys.empty() ? paths.required : paths.containers).insert(path);
      walk(*variant, path, paths);
    }
    for (const auto& key : rule.keys) {
      const std::string path = prefix + "/" + std::string(key.key);
      if (!key.object || documented_elsewhere_.count(key.object)) {
        paths.required.insert(path);
        continue;
      }
      paths.containers.insert(path);
      walk(*key.object, key.type == ValueType::object_array ? path + "/*" : path, paths);
    }
  }

private:
  std::set<const ObjectRule*> documented_elsewhere_;
};

// The walker that stops at every rule with a section or a method block of its own.
PathWalker scene_walker() {
  std::set<const ObjectRule*> elsewhere;
  for (const TypeSection& section : type_sections()) elsewhere.insert(section.rule);
  for (const auto& method : cli::registered_methods()) elsewhere.insert(method.scene_block.rule);
  return PathWalker(elsewhere);
}

// Full paths of the scene and every method block ("/discretization/dg/degree").
RulePaths full_rule_paths() {
  RulePaths paths;
  const PathWalker walker = scene_walker();
  walker.walk(scene_schema::scene_rule(), "", paths);
  for (const auto& method : cli::registered_methods()) {
    const std::string block = "/discretization/" + std::string(method.scene_block.name);
    paths.containers.insert(block);
    walker.walk(*method.scene_block.rule, block, paths);
  }
  return paths;
}

// A type section's paths relative to its rule ("box/min"), with its prefix.
RulePaths relative_rule_paths(const TypeSection& section) {
  RulePaths walked;
  scene_walker().walk(*section.rule, "", walked);
  RulePaths paths;
  for (const std::string& path : walked.required) paths.required.insert(section.prefix + path.substr(1));
  for (const std::string& path : walked.containers) paths.containers.insert(section.prefix + path.substr(1));
  return paths;
}

// The document's paths by section: rows "| `/a/b` | …" under "full", rows "| `box/min`,
// `box/max` | …" under their type section's heading; relative rows elsewhere under "?".
std::map<std::string, std::vector<std::string>> document_paths() {
  std::set<std::string> type_headings;
  for (const TypeSection& section : type_sections()) type_headings.insert(section.heading);
  std::ifstream stream(std::string(ALTFEM_SOURCE_DIR) + "/docs/scene-schema.md");
  std::map<std::string, std::vector<std::string>> paths;
  std::string heading;
  for (std::string line; std::getline(stream, line);) {
    if (line.rfind('#', 0) == 0) {
      heading = line.substr(line.find_first_not_of("# "));
      continue;
    }
    if (line.rfind("| `", 0) != 0) continue;
    const std::string cell = line.substr(1, line.find('|', 1) - 1);
    for (std::size_t open = cell.find('`'); open != std::string::npos;
         open = cell.find('`', cell.find('`', open + 1) + 1)) {
      const std::string path = cell.substr(open + 1, cell.find('`', open + 1) - open - 1);
      const std::string section = path.rfind('/', 0) == 0 ? "full" : type_headings.count(heading) ? heading : "?";
      paths[section].push_back(path);
    }
  }
  return paths;
}

void expect_same_paths(const RulePaths& rules, const std::vector<std::string>& documented, const std::string& where) {
  const std::set<std::string> rows(documented.begin(), documented.end());
  for (const std::string& path : rules.required)
    EXPECT_TRUE(rows.count(path)) << "docs/scene-schema.md has no row for '" << path << "' (" << where << ")";
  for (const std::string& path : rows)
    EXPECT_TRUE(rules.required.count(path) || rules.containers.count(path))
        << "docs/scene-schema.md documents '" << path << "' (" << where << "), which no rule has";
}

TEST(SchemaDocument, EveryFullPathHasARowAndEveryRowAPath) {
  const auto documented = document_paths();
  ASSERT_TRUE(documented.count("full"));
  EXPECT_GE(documented.at("full").size(), 100u);
  expect_same_paths(full_rule_paths(), documented.at("full"), "full paths");
  EXPECT_FALSE(documented.count("?")) << "a relative path outside the type sections: " << documented.at("?").front();
}

TEST(SchemaDocument, EveryTypeSectionMatchesItsRule) {
  const auto documented = document_paths();
  for (const TypeSection& section : type_sections()) {
    ASSERT_NE(section.rule, nullptr) << section.heading;
    ASSERT_TRUE(documented.count(section.heading)) << "no section '" << section.heading << "'";
    expect_same_paths(relative_rule_paths(section), documented.at(section.heading), section.heading);
  }
}

}  // namespace
}  // namespace altfem
