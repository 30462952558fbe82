// docs/scene-schema.md and the schema rules say the same thing: every key of every
// rule (shared/scene's and each registered method's block) has a row in the document,
// and every row names a key some rule knows.
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "app/method_registry.hpp"
#include "shared/scene/scene_schema.hpp"

namespace altfem {
namespace {

using scene_schema::ObjectRule;

void collect_keys(const ObjectRule& rule, std::set<std::string>& keys, std::set<const ObjectRule*>& seen) {
  if (!seen.insert(&rule).second) return;  // shapes nest recursively
  if (!rule.tag.empty()) keys.insert(std::string(rule.tag));
  for (const auto& [name, variant] : rule.variants) {
    keys.insert(std::string(name));
    collect_keys(*variant, keys, seen);
  }
  for (const auto& key : rule.keys) {
    keys.insert(std::string(key.key));
    if (key.object) collect_keys(*key.object, keys, seen);
  }
}

std::set<std::string> rule_keys() {
  std::set<std::string> keys;
  std::set<const ObjectRule*> seen;
  collect_keys(scene_schema::scene_rule(), keys, seen);
  for (const auto& method : cli::registered_methods()) {
    keys.insert(std::string(method.scene_block.name));
    collect_keys(*method.scene_block.rule, keys, seen);
  }
  return keys;
}

// The paths in the first cell of the document's key tables, split into segments:
// "| `box/min`, `box/max` | …" gives {box, min} and {box, max}.
std::vector<std::vector<std::string>> document_paths() {
  std::ifstream stream(std::string(ALTFEM_SOURCE_DIR) + "/docs/scene-schema.md");
  std::vector<std::vector<std::string>> paths;
  for (std::string line; std::getline(stream, line);) {
    if (line.rfind("| `", 0) != 0) continue;
    const std::string cell = line.substr(1, line.find('|', 1) - 1);
    for (std::size_t open = cell.find('`'); open != std::string::npos; open = cell.find('`', cell.find('`', open + 1) + 1)) {
      const std::size_t close = cell.find('`', open + 1);
      std::vector<std::string> segments;
      std::stringstream path(cell.substr(open + 1, close - open - 1));
      for (std::string segment; std::getline(path, segment, '/');)
        if (!segment.empty() && segment != "*") segments.push_back(segment);
      paths.push_back(segments);
    }
  }
  return paths;
}

TEST(SchemaDocument, EveryRuleKeyHasARow) {
  std::set<std::string> documented;
  for (const auto& path : document_paths()) documented.insert(path.begin(), path.end());
  for (const auto& key : rule_keys()) EXPECT_TRUE(documented.count(key)) << "no row in docs/scene-schema.md for '" << key << "'";
}

TEST(SchemaDocument, EveryRowNamesAKeyOfTheRules) {
  const std::set<std::string> known = rule_keys();
  std::set<std::string> documented;
  for (const auto& path : document_paths()) documented.insert(path.back());
  EXPECT_GE(documented.size(), 40u);
  for (const auto& key : documented) EXPECT_TRUE(known.count(key)) << "docs/scene-schema.md documents '" << key << "', which no rule has";
}

}  // namespace
}  // namespace altfem
