#pragma once
// A test helper: a scene written as JSON text into the build folder's unit_dg/.
#include <filesystem>
#include <fstream>
#include <string>

namespace altfem::test {

inline std::filesystem::path write_scene_file(const std::string& name, const std::string& json) {
  const auto folder = std::filesystem::path(ALTFEM_BINARY_DIR) / "unit_dg";
  std::filesystem::create_directories(folder);
  const auto file = folder / (name + ".json");
  std::ofstream(file) << json;
  return file;
}

}  // namespace altfem::test
