#include "shared/io/atomic_file.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "tests/unit/io/io_test_support.hpp"

namespace altfem {
namespace {

std::string read_text(const std::filesystem::path& path) {
  std::ifstream stream(path, std::ios::binary);
  std::ostringstream text;
  text << stream.rdbuf();
  return text.str();
}

std::vector<std::string> folder_entries(const std::filesystem::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(AtomicFile, ReplacesAnExistingFileWholeAndLeavesNoTemporaryFile) {
  const auto folder = test::fresh_output_directory();
  const auto file = folder / "summary.txt";
  write_file_atomically(file, std::string(100000, 'x'));
  EXPECT_EQ(std::filesystem::file_size(file), 100000u);
  const std::string shorter("short\0binary\n", 13);
  write_file_atomically(file, shorter);
  EXPECT_EQ(read_text(file), shorter);
  EXPECT_EQ(folder_entries(folder), std::vector<std::string>{"summary.txt"});
}

TEST(AtomicFile, MissingFolderThrowsNamingThePath) {
  const auto folder = test::fresh_output_directory();
  const auto file = folder / "missing" / "frame.vtu";
  try {
    write_file_atomically(file, "content");
    FAIL() << "wrote into a missing folder";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(file.string()), std::string::npos) << error.what();
  }
  EXPECT_TRUE(folder_entries(folder).empty());
}

TEST(AtomicFile, FailedRenameRemovesTheTemporaryFile) {
  const auto folder = test::fresh_output_directory();
  // A non-empty folder in the way: the rename over it fails after the temporary
  // file was written.
  std::filesystem::create_directories(folder / "occupied" / "inside");
  EXPECT_THROW(write_file_atomically(folder / "occupied", "content"), std::runtime_error);
  EXPECT_EQ(folder_entries(folder), std::vector<std::string>{"occupied"});
}

}  // namespace
}  // namespace altfem
