#include "shared/io/vtu_writer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numeric>

#include "shared/common/error.hpp"
#include "tests/unit/io/io_test_support.hpp"

namespace altfem {
namespace {

/// #points × 3 distinct, non-round coordinates, so a permuted or truncated array shows.
Eigen::MatrixXd scattered_points(int count) {
  Eigen::MatrixXd points(count, 3);
  for (int i = 0; i < count; ++i) points.row(i) << 0.1 * i, std::sin(i), 1.0 / (i + 3.0);
  return points;
}

/// One row of consecutive point ids first, first + 1, ...
Eigen::MatrixXi consecutive_cell(int first, int nodes) {
  Eigen::MatrixXi cell(1, nodes);
  std::iota(cell.data(), cell.data() + nodes, first);
  return cell;
}

/// A cube [0,1]³ (points 0–7) with a pyramid on its top face (apex 8), both as
/// VTK_POLYHEDRON with outward faces. The pyramid comes first: meshio 5 groups
/// polyhedra by point count for the cells but by ascending point count for the cell
/// data, so only this order keeps its cell data aligned.
UnstructuredGrid cube_and_pyramid() {
  UnstructuredGrid grid;
  grid.points.resize(9, 3);
  grid.points << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1, 0.5, 0.5, 1.5;
  grid.add_polyhedron({{4, 7, 6, 5}, {4, 5, 8}, {5, 6, 8}, {6, 7, 8}, {7, 4, 8}});
  grid.add_polyhedron({{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}});
  grid.cell_data.emplace_back("volume", Eigen::Vector2d(1.0 / 6.0, 1.0));
  return grid;
}

/// cube_and_pyramid followed by a VTK_TETRA in the cube's corner.
UnstructuredGrid cube_pyramid_and_tetrahedron() {
  UnstructuredGrid grid = cube_and_pyramid();
  Eigen::MatrixXi tet(1, 4);
  tet << 0, 1, 3, 4;
  grid.add_cells(ElementType::tet4, tet);
  Eigen::MatrixXd& volume = grid.cell_data.front().second;
  volume.resize(3, 1);
  volume << 1.0 / 6.0, 1.0, 1.0 / 6.0;
  return grid;
}

TEST(VtuWriter, MixedTetAndHexCellsWithDataReadBackByMeshio) {
  UnstructuredGrid grid;
  grid.points = scattered_points(49);
  grid.add_cells(ElementType::tet10, consecutive_cell(0, 10));
  grid.add_cells(ElementType::hex27, consecutive_cell(10, 27));
  grid.add_cells(ElementType::hex8, consecutive_cell(37, 8));
  grid.add_cells(ElementType::tet4, consecutive_cell(45, 4));
  grid.add_cells(ElementType::tet10, consecutive_cell(39, 10));  // a second Tet10 block, sharing points
  EXPECT_EQ(grid.cell_types, (std::vector<int>{24, 29, 12, 10, 24}));
  EXPECT_EQ(grid.offsets, (std::vector<int64_t>{10, 37, 45, 49, 59}));

  Eigen::MatrixXd displacement(49, 3);
  for (int i = 0; i < 49; ++i) displacement.row(i) << 0.5 * i, -1.0 * i, 1e-3 * i * i;
  grid.point_data.emplace_back("displacement", displacement);
  grid.point_data.emplace_back("temperature", grid.points.col(1));
  grid.cell_data.emplace_back("material_id", Eigen::Matrix<double, 5, 1>(3, 1, 4, 1, 5));

  const auto file = test::fresh_output_directory() / "mixed.vtu";
  write_vtu(file, grid);
  EXPECT_EQ(test::run_checker("vtu", file, test::expected_contents(grid, {{"24", 2}, {"29", 1}, {"12", 1}, {"10", 1}})),
            0);
}

TEST(VtuWriter, TriangleGridReadBackByMeshio) {
  UnstructuredGrid grid;
  grid.points = scattered_points(5);
  Eigen::MatrixXi triangles(3, 3);
  triangles << 0, 1, 2, 0, 2, 3, 0, 3, 4;
  grid.add_triangles(triangles);
  grid.point_data.emplace_back("normal", scattered_points(5).rowwise().reverse());
  grid.cell_data.emplace_back("area", Eigen::Vector3d(0.25, 0.5, 0.125));

  const auto file = test::fresh_output_directory() / "triangles.vtu";
  write_vtu(file, grid);
  EXPECT_EQ(test::run_checker("vtu", file, test::expected_contents(grid, {{"5", 3}})), 0);
}

TEST(VtuWriter, CubicLagrangeTetrahedraReadBackByMeshio) {
  UnstructuredGrid grid;
  grid.points = scattered_points(40);
  Eigen::MatrixXi cells(2, 20);
  cells.row(0) = consecutive_cell(0, 20);
  cells.row(1) = consecutive_cell(20, 20);
  grid.add_cells(ElementType::tet20, cells);
  EXPECT_EQ(grid.cell_types, (std::vector<int>{71, 71}));
  grid.point_data.emplace_back("displacement", 2.0 * grid.points);
  grid.cell_data.emplace_back("error", Eigen::Vector2d(1e-300, 7.5));

  const auto file = test::fresh_output_directory() / "tet20.vtu";
  write_vtu(file, grid);
  EXPECT_EQ(test::run_checker("vtu", file, test::expected_contents(grid, {{"71", 2}})), 0);
}

TEST(VtuWriter, PolyhedraReadBackByMeshio) {
  UnstructuredGrid grid = cube_and_pyramid();
  // The connectivity of a polyhedron is its distinct points in order of first appearance.
  EXPECT_EQ(grid.connectivity, (std::vector<int64_t>{4, 7, 6, 5, 8, 0, 3, 2, 1, 4, 5, 6, 7}));
  EXPECT_EQ(grid.offsets, (std::vector<int64_t>{5, 13}));
  grid.point_data.emplace_back("displacement", grid.points * 0.5);

  const auto file = test::fresh_output_directory() / "polyhedra.vtu";
  write_vtu(file, grid);
  EXPECT_EQ(test::run_checker("vtu", file, test::expected_contents(grid, {{"42", 2}})), 0);
  EXPECT_EQ(test::run_checker("raw", file, {{"arrays", nlohmann::json::object()}, {"without_components", {"faces"}}}),
            0);
}

TEST(VtuWriter, PolyhedraMixedWithOtherCellsFollowVtkFaceStream) {
  const UnstructuredGrid grid = cube_pyramid_and_tetrahedron();

  const auto file = test::fresh_output_directory() / "mixed_polyhedra.vtu";
  write_vtu(file, grid);
  // VTK's face stream: per polyhedron #faces, then #points and ids of each face;
  // faceoffsets is each cell's end in it, −1 for a cell that is not a polyhedron.
  const nlohmann::json arrays = {
      {"types", {42, 42, 10}},
      {"connectivity", {4, 7, 6, 5, 8, 0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 3, 4}},
      {"offsets", {5, 13, 17}},
      {"volume", {1.0 / 6.0, 1.0, 1.0 / 6.0}},
      {"faceoffsets", {22, 53, -1}},
      {"faces", {5, 4, 4, 7, 6, 5, 3, 4, 5, 8, 3, 5, 6, 8, 3, 6, 7, 8, 3, 7, 4, 8, 6, 4, 0, 3, 2,
                 1, 4, 4, 5, 6, 7, 4, 0, 1, 5, 4, 4, 1, 2, 6, 5, 4, 2, 3, 7, 6, 4, 3, 0, 4, 7}}};
  EXPECT_EQ(test::run_checker("raw", file, {{"arrays", arrays}, {"without_components", {"faces", "faceoffsets"}}}), 0);
}

TEST(VtuWriter, PolyhedraMixedWithOtherCellsReadBackByVtk) {
  const UnstructuredGrid grid = cube_pyramid_and_tetrahedron();
  const auto file = test::fresh_output_directory() / "mixed_polyhedra.vtu";
  write_vtu(file, grid);
  // meshio 5 cannot read polyhedra mixed with other cells; VTK itself can.
  const int vtk_result = test::run_checker("vtk", file, test::expected_contents(grid, nlohmann::json::object()));
  if (vtk_result == 77) GTEST_SKIP() << "python3-vtk9 is not installed";
  EXPECT_EQ(vtk_result, 0);
}

TEST(VtuWriter, VolumeMeshBecomesOneCellBlock) {
  VolumeMesh mesh;
  mesh.element_type = ElementType::hex8;
  mesh.nodes = scattered_points(12);
  mesh.cells.resize(2, 8);
  mesh.cells << 0, 1, 2, 3, 4, 5, 6, 7, 4, 5, 6, 7, 8, 9, 10, 11;
  const UnstructuredGrid grid = grid_from_volume_mesh(mesh);
  EXPECT_EQ(grid.points, mesh.nodes);
  EXPECT_EQ(grid.cell_types, (std::vector<int>{12, 12}));
  EXPECT_EQ(grid.offsets, (std::vector<int64_t>{8, 16}));
  EXPECT_EQ(grid.connectivity[8], 4);

  const auto file = test::fresh_output_directory() / "volume_mesh.vtu";
  write_vtu(file, grid);
  EXPECT_EQ(test::run_checker("vtu", file, test::expected_contents(grid, {{"12", 2}})), 0);
}

TEST(VtuWriter, RejectsInconsistentGrids) {
  UnstructuredGrid grid;
  grid.points = scattered_points(5);
  EXPECT_THROW(grid.add_cells(ElementType::tet10, consecutive_cell(0, 4)), std::invalid_argument);
  grid.add_cells(ElementType::tet4, consecutive_cell(0, 4));
  EXPECT_NO_THROW(vtu_text(grid, "ok.vtu"));

  UnstructuredGrid wrong_count = grid;
  wrong_count.connectivity.push_back(4);
  wrong_count.offsets.back() = 5;  // five points for a VTK_TETRA
  EXPECT_THROW(vtu_text(wrong_count, "bad.vtu"), std::invalid_argument);

  UnstructuredGrid out_of_range = grid;
  out_of_range.connectivity[2] = 5;
  EXPECT_THROW(vtu_text(out_of_range, "bad.vtu"), std::invalid_argument);

  UnstructuredGrid short_data = grid;
  short_data.point_data.emplace_back("displacement", Eigen::MatrixXd::Zero(4, 3));
  EXPECT_THROW(vtu_text(short_data, "bad.vtu"), std::invalid_argument);

  UnstructuredGrid faces_on_a_tet = grid;
  faces_on_a_tet.polyhedron_faces[0] = {{0, 1, 2}};
  EXPECT_THROW(vtu_text(faces_on_a_tet, "bad.vtu"), std::invalid_argument);
}

TEST(VtuWriter, RefusesNaNNamingTheArrayAndLeavesNoFile) {
  UnstructuredGrid grid;
  grid.points = scattered_points(4);
  grid.add_cells(ElementType::tet4, consecutive_cell(0, 4));
  Eigen::MatrixXd displacement = Eigen::MatrixXd::Zero(4, 3);
  displacement(2, 1) = std::numeric_limits<double>::quiet_NaN();
  grid.point_data.emplace_back("displacement", displacement);

  const auto file = test::fresh_output_directory() / "nan.vtu";
  try {
    write_vtu(file, grid);
    FAIL() << "NaN was written";
  } catch (const NumericalError& error) {
    EXPECT_NE(std::string(error.what()).find("'displacement', row 2"), std::string::npos) << error.what();
  }
  EXPECT_FALSE(std::filesystem::exists(file));
}

}  // namespace
}  // namespace altfem
