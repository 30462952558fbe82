// Every malformed input of tests/data/bad/ (listed with the message it must produce
// in each folder's EXPECTED.txt) gives exit code 2, exactly one line on stderr that
// names the file and says what was wrong, and leaves no output folder behind.
#include <gtest/gtest.h>

#include <fstream>

#include "tests/cli/cli_support.hpp"

namespace altfem::test {
namespace {

struct BadInput {
  std::string file;      // in tests/data/bad/<kind>/
  std::string expected;  // a substring of the message
};

// Names a parameter by its file in test output (instead of its bytes).
void PrintTo(const BadInput& input, std::ostream* out) { *out << input.file; }

std::vector<BadInput> read_expected(const std::string& kind) {
  std::vector<BadInput> inputs;
  std::ifstream in(source_path("tests/data/bad/" + kind + "/EXPECTED.txt"));
  for (std::string line; std::getline(in, line);) {
    const auto tab = line.find('\t');
    if (line.empty() || line[0] == '#' || tab == std::string::npos) continue;
    inputs.push_back({line.substr(0, tab), line.substr(tab + 1)});
  }
  return inputs;
}

// A scene whose geometry is the given surface or volume-mesh file.
std::filesystem::path scene_for_geometry(const std::filesystem::path& geometry, const std::filesystem::path& folder) {
  const std::string extension = geometry.extension().string();
  const bool mesh = extension == ".msh" || extension == ".mesh";
  const auto scene = folder / "scene.json";
  std::ofstream out(scene);
  out << R"({ "geometry": { ")" << (mesh ? "mesh" : "surface") << R"(": ")" << geometry.string()
      << R"(" }, "material": { "youngs_modulus": 1e6, "poisson_ratio": 0.3 } })";
  return scene;
}

void expect_bad_input(const CommandResult& result, const std::string& file, const std::string& expected) {
  EXPECT_EQ(result.exit_code, 2) << result.err;
  const auto lines = lines_of(result.err);
  ASSERT_EQ(lines.size(), 1u) << "expected one line on stderr, got:\n" << result.err;
  EXPECT_NE(lines[0].find(file), std::string::npos) << "the message does not name " << file << ": " << lines[0];
  EXPECT_NE(lines[0].find(expected), std::string::npos) << "expected '" << expected << "' in: " << lines[0];
}

class BadScene : public testing::TestWithParam<BadInput> {};

TEST_P(BadScene, CheckAndRunRejectWithOneLineAndNoOutput) {
  const auto scene = source_path("tests/data/bad/scene/" + GetParam().file);
  expect_bad_input(run_altfem({"check", scene.string()}), GetParam().file, GetParam().expected);
  const auto out = fresh_directory("bad-scene") / "run";
  // `run` resolves its own method's block only: a fixture whose message names another
  // method's block runs that method.
  std::string method = "fem";
  for (const char* other : {"dg", "harmonic"})
    if (GetParam().expected.find("/discretization/" + std::string(other) + "/") != std::string::npos) method = other;
  expect_bad_input(run_altfem({"run", scene.string(), "--method", method, "--out", out.string()}), GetParam().file,
                   GetParam().expected);
  EXPECT_FALSE(std::filesystem::exists(out)) << "a rejected run left " << out;
}

INSTANTIATE_TEST_SUITE_P(Fixtures, BadScene, testing::ValuesIn(read_expected("scene")),
                         [](const auto& info) { return info.param.file.substr(0, info.param.file.find('.')); });

class BadGeometry : public testing::TestWithParam<BadInput> {};

TEST_P(BadGeometry, CheckAndRunRejectWithOneLineAndNoOutput) {
  const auto folder = fresh_directory("bad-geometry");
  const std::filesystem::path geometry = source_path("tests/data/bad/mesh/" + GetParam().file);
  const auto scene = scene_for_geometry(geometry, folder);
  // A file type no reader knows is refused by the scene validator before any
  // reader runs; its message names the scene key and the file.
  const std::string extension = geometry.extension().string();
  const bool known = extension == ".msh" || extension == ".mesh" || extension == ".off" || extension == ".obj" ||
                     extension == ".stl" || extension == ".ply";
  const std::string expected = known ? GetParam().expected : "/geometry/surface: expected a file ending in one of";
  expect_bad_input(run_altfem({"check", scene.string()}), GetParam().file, expected);
  const auto out = folder / "run";
  expect_bad_input(run_altfem({"run", scene.string(), "--method", "fem", "--out", out.string()}), GetParam().file,
                   expected);
  EXPECT_FALSE(std::filesystem::exists(out)) << "a rejected run left " << out;
}

INSTANTIATE_TEST_SUITE_P(Fixtures, BadGeometry, testing::ValuesIn(read_expected("mesh")), [](const auto& info) {
  std::string name = info.param.file;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
});

TEST(BadCommandLine, MissingSceneFile) {
  expect_bad_input(run_altfem({"check", "/nonexistent/scene.json"}), "/nonexistent/scene.json", "");
}

TEST(BadCommandLine, DirectoryInsteadOfSceneFile) {
  const auto folder = fresh_directory("directory-scene");
  expect_bad_input(run_altfem({"check", folder.string()}), folder.string(), "");
}

TEST(BadCommandLine, UnknownMethodNamesTheAvailableOnes) {
  const auto out = fresh_directory("unknown-method") / "run";
  const auto result = run_altfem(
      {"run", source_path("scenes/cantilever.json").string(), "--method", "boundary_elements", "--out", out.string()});
  expect_bad_input(result, "--method", "available: fem");
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(BadCommandLine, UnknownSubcommandAndMissingMethodAreBadInput) {
  EXPECT_EQ(run_altfem({"simulate"}).exit_code, 2);
  EXPECT_EQ(run_altfem({"run", source_path("scenes/cantilever.json").string()}).exit_code, 2);
}

}  // namespace
}  // namespace altfem::test
