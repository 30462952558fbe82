#pragma once
// Support for the io tests: a fresh output folder per test, and check_vtu.py, which
// reads written files back with meshio (and python3-vtk9 when installed): an
// independent reader is the real test of a writer.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "shared/io/json_file.hpp"
#include "shared/io/unstructured_grid.hpp"

namespace altfem::test {

/// An empty folder for one test's files under the build tree.
inline std::filesystem::path fresh_output_directory() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path folder = std::filesystem::path(ALTFEM_BINARY_DIR) / "test_output" / "unit_io" /
                                       (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder;
}

/// What the checker should read back: points, each cell (VTK type and point ids, or
/// faces for a polyhedron), the number of cells per VTK type, point and cell data.
inline nlohmann::json expected_contents(const UnstructuredGrid& grid, const nlohmann::json& cell_counts) {
  auto rows = [](const Eigen::MatrixXd& matrix) {
    nlohmann::json result = nlohmann::json::array();
    for (Eigen::Index row = 0; row < matrix.rows(); ++row) {
      nlohmann::json values = nlohmann::json::array();
      for (Eigen::Index column = 0; column < matrix.cols(); ++column) values.push_back(matrix(row, column));
      result.push_back(values);
    }
    return result;
  };
  nlohmann::json expected{{"points", rows(grid.points)},
                          {"cells", nlohmann::json::array()},
                          {"cell_counts", cell_counts},
                          {"point_data", nlohmann::json::object()},
                          {"cell_data", nlohmann::json::object()}};
  int64_t begin = 0;
  for (int64_t cell = 0; cell < grid.cell_count(); ++cell) {
    if (grid.cell_types[cell] == vtk_polyhedron)
      expected["cells"].push_back({{"type", 42}, {"faces", grid.polyhedron_faces[cell]}});
    else
      expected["cells"].push_back({{"type", grid.cell_types[cell]},
                                   {"points", std::vector<int64_t>(grid.connectivity.begin() + begin,
                                                                   grid.connectivity.begin() + grid.offsets[cell])}});
    begin = grid.offsets[cell];
  }
  for (const auto& [name, values] : grid.point_data) expected["point_data"][name] = rows(values);
  for (const auto& [name, values] : grid.cell_data) expected["cell_data"][name] = rows(values);
  return expected;
}

/// Exit code of `check_vtu.py mode file expected` (0 = the file matches).
inline int run_checker(const std::string& mode, const std::filesystem::path& file, const nlohmann::json& expected) {
  const std::filesystem::path expected_file = file.string() + "." + mode + ".expected.json";
  write_json_file(expected_file, expected);
  const std::filesystem::path script = std::filesystem::path(ALTFEM_SOURCE_DIR) / "tests/unit/io/check_vtu.py";
  // /usr/bin/python3 explicitly: the python3 on PATH may lack numpy and meshio.
  const std::string command = "/usr/bin/python3 '" + script.string() + "' " + mode + " '" + file.string() + "' '" +
                              expected_file.string() + "'";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace altfem::test
