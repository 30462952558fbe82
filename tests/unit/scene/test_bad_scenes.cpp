// Every fixture of tests/data/bad/scene fails with the one-line message EXPECTED.txt names.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "app/method_registry.hpp"
#include "shared/common/error.hpp"
#include "shared/scene/scene.hpp"
#include "shared/scene/scene_geometry.hpp"

namespace altfem {
namespace {

const std::filesystem::path folder = std::filesystem::path(ALTFEM_SOURCE_DIR) / "tests/data/bad/scene";

struct Expectation {
  std::string file;
  std::string message;
};

std::vector<Expectation> expectations() {
  std::vector<Expectation> result;
  std::ifstream stream(folder / "EXPECTED.txt");
  std::string line;
  while (std::getline(stream, line)) {
    const auto tab = line.find('\t');
    if (tab == std::string::npos) continue;
    result.push_back({line.substr(0, tab), line.substr(tab + 1)});
  }
  return result;
}

TEST(BadScenes, EveryFixtureIsListedOnce) {
  std::set<std::string> listed;
  for (const auto& expectation : expectations())
    EXPECT_TRUE(listed.insert(expectation.file).second) << expectation.file;
  std::set<std::string> present;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    if (entry.path().extension() == ".json") present.insert(entry.path().filename().string());
  EXPECT_EQ(listed, present);
  EXPECT_GE(present.size(), 15u);
}

TEST(BadScenes, EveryFixtureFailsWithItsMessage) {
  for (const auto& expectation : expectations()) {
    SCOPED_TRACE(expectation.file);
    const std::filesystem::path path = folder / expectation.file;
    try {
      // What `altfem check` does: the common keys, every method's block, the geometry.
      Scene scene = load_scene(path);
      cli::resolve_method_blocks(scene, cli::available_methods());
      load_scene_geometry(scene);
      ADD_FAILURE() << "no error";
    } catch (const InputError& error) {
      const std::string message = error.what();
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      EXPECT_EQ(message.rfind(path.string(), 0), 0u) << message;
      EXPECT_NE(message.find(expectation.message), std::string::npos) << message;
    }
  }
}

TEST(BadScenes, MissingSceneFileIsAnInputError) {
  EXPECT_THROW(load_scene(folder / "does_not_exist.json"), InputError);
}

TEST(BadScenes, SyntaxErrorsNameLineAndColumn) {
  try {
    parse_scene("{\n  \"name\": \"x\",\n  \"material\": [1,,2]\n}", "inline.json");
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("inline.json: line 3, column 18: JSON syntax error"), std::string::npos)
        << error.what();
  }
}

TEST(BadScenes, NestingIsBounded) {
  const std::string sphere = R"({"sphere": {"centre": [0, 0, 0], "radius": 1}})";
  std::string shape = sphere;
  for (int i = 0; i < 100; ++i) shape = R"({"union": [)" + shape + "," + sphere + "]}";
  const std::string text =
      R"({"geometry": {"shape": )" + shape + R"(}, "material": {"youngs_modulus": 1, "poisson_ratio": 0}})";
  EXPECT_THROW(parse_scene(text, "deep.json"), InputError);
}

}  // namespace
}  // namespace altfem
