#include "shared/io/pvd_collection.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "shared/common/error.hpp"
#include "shared/io/vtu_writer.hpp"
#include "tests/unit/io/io_test_support.hpp"

namespace altfem {
namespace {

TEST(PvdCollection, TimeSeriesReadBackFrameByFrame) {
  const auto folder = test::fresh_output_directory();
  std::filesystem::create_directories(folder / "frames");
  UnstructuredGrid grid;
  grid.points.resize(4, 3);
  grid.points << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  Eigen::MatrixXi tet(1, 4);
  tet << 0, 1, 2, 3;
  grid.add_cells(ElementType::tet4, tet);
  grid.point_data.emplace_back("displacement", Eigen::MatrixXd::Zero(4, 3));

  PvdCollection collection(folder / "run.pvd");
  nlohmann::json expected{{"datasets", nlohmann::json::array()}};
  const double times[] = {0.0, 0.1, 1.0 / 3.0};
  for (int frame = 0; frame < 3; ++frame) {
    grid.point_data[0].second = (frame + 1.0) * grid.points;
    const std::string name = "frames/frame_" + std::to_string(frame) + ".vtu";
    write_vtu(folder / name, grid);
    // The last frame is given by its absolute path: the collection stores it relative.
    collection.add(times[frame], frame == 2 ? folder / name : std::filesystem::path(name));
    collection.write();  // rewritten after every frame, as a run does
    expected["datasets"].push_back({{"timestep", times[frame]},
                                    {"part", 0},
                                    {"file", name},
                                    {"content", test::expected_contents(grid, {{"10", 1}})}});
  }
  EXPECT_EQ(test::run_checker("pvd", folder / "run.pvd", expected), 0);
}

TEST(PvdCollection, RefusesNonFiniteTime) {
  PvdCollection collection("unused.pvd");
  EXPECT_THROW(collection.add(std::numeric_limits<double>::infinity(), "frame.vtu"), NumericalError);
}

}  // namespace
}  // namespace altfem
