// Every fixture in tests/data/bad/mesh/ must fail with one InputError line that names
// the file and contains the substring EXPECTED.txt gives for it (the CLI tests reuse
// the same manifest).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "shared/common/error.hpp"
#include "shared/mesh/surface_mesh.hpp"
#include "shared/mesh/text_file.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem {
namespace {

const std::filesystem::path fixtures = std::filesystem::path(ALTFEM_SOURCE_DIR) / "tests/data/bad/mesh";

std::string error_message(const std::filesystem::path& path) {
  try {
    const std::string extension = lowercase_extension(path);
    if (extension == ".msh" || extension == ".mesh") read_volume_mesh(path);
    else read_surface(path);
  } catch (const InputError& error) {
    return error.what();
  }
  return "no InputError";
}

TEST(BadMeshInput, EveryFixtureFailsWithItsExpectedOneLineMessage) {
  std::ifstream manifest(fixtures / "EXPECTED.txt");
  ASSERT_TRUE(manifest) << "missing EXPECTED.txt";
  std::set<std::string> listed;
  std::string line;
  while (std::getline(manifest, line)) {
    if (line.empty() || line[0] == '#') continue;
    const auto tab = line.find('\t');
    ASSERT_NE(tab, std::string::npos) << "EXPECTED.txt line without a tab: " << line;
    const std::string name = line.substr(0, tab);
    const std::string expected = line.substr(tab + 1);
    listed.insert(name);
    const std::string message = error_message(fixtures / name);
    EXPECT_NE(message.find(name), std::string::npos) << name << ": " << message;
    EXPECT_NE(message.find(expected), std::string::npos) << name << ": " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << name << ": " << message;
  }
  EXPECT_GE(listed.size(), 15u);
  // Every fixture is listed, so none is silently left untested.
  for (const auto& entry : std::filesystem::directory_iterator(fixtures)) {
    const std::string name = entry.path().filename().string();
    if (name != "EXPECTED.txt") {
      EXPECT_TRUE(listed.count(name)) << name << " is not in EXPECTED.txt";
    }
  }
}

TEST(BadMeshInput, MissingFilesAndDirectoriesAreInputErrors) {
  EXPECT_NE(error_message(fixtures / "no_such_file.msh").find("no_such_file.msh: no such file"), std::string::npos);
  EXPECT_NE(error_message(fixtures / "no_such_file.off").find("no_such_file.off: no such file"), std::string::npos);
  const std::filesystem::path folder = std::filesystem::path(ALTFEM_BINARY_DIR) / "tests" / "folder.msh";
  std::filesystem::create_directories(folder);
  EXPECT_NE(error_message(folder).find("folder.msh: is a directory"), std::string::npos);
}

}  // namespace
}  // namespace altfem
