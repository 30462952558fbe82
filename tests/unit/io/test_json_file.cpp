#include "shared/io/json_file.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <limits>

#include "shared/common/error.hpp"
#include "tests/unit/io/io_test_support.hpp"

namespace altfem {
namespace {

nlohmann::json summary() {
  return {{"scene", "bunny_drop"},
          {"timings_s", {{"setup", 0.25}, {"solve", 1.5}}},
          {"newton_iterations", {3, 4, 2}},
          {"status", "ok"}};
}

TEST(JsonFile, WritesPrettyJsonThatReadsBackEqual) {
  const auto file = test::fresh_output_directory() / "summary.json";
  write_json_file(file, summary());
  std::ifstream stream(file);
  const std::string text((std::istreambuf_iterator<char>(stream)), std::istreambuf_iterator<char>());
  EXPECT_EQ(nlohmann::json::parse(text), summary());
  EXPECT_NE(text.find("\n  \"scene\": \"bunny_drop\""), std::string::npos) << text;
  EXPECT_EQ(text.back(), '\n');
}

TEST(JsonFile, RefusesNaNNamingTheKeyAndKeepsTheOldFile) {
  const auto file = test::fresh_output_directory() / "summary.json";
  write_json_file(file, summary());
  nlohmann::json broken = summary();
  broken["timings_s"]["solve"] = std::numeric_limits<double>::quiet_NaN();
  try {
    write_json_file(file, broken);
    FAIL() << "NaN was written";
  } catch (const NumericalError& error) {
    EXPECT_NE(std::string(error.what()).find("/timings_s/solve"), std::string::npos) << error.what();
  }
  broken = summary();
  broken["newton_iterations"][1] = -std::numeric_limits<double>::infinity();
  try {
    write_json_file(file, broken);
    FAIL() << "-inf was written";
  } catch (const NumericalError& error) {
    EXPECT_NE(std::string(error.what()).find("/newton_iterations/1"), std::string::npos) << error.what();
  }
  std::ifstream stream(file);
  EXPECT_EQ(nlohmann::json::parse(stream), summary());
}

}  // namespace
}  // namespace altfem
