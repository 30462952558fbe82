// The surface error of docs/conventions.md ("Metrics") on synthetic data with known answers,
// the transfer to a differently meshed surface, and the VTU read back from write_vtu.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "shared/common/error.hpp"
#include "shared/compare/surface_error.hpp"
#include "shared/io/vtu_writer.hpp"

namespace altfem {
namespace {

// The unit square z = 0 as two triangles; the rest positions.
SurfaceFrame square(const Eigen::MatrixX3d& displacement) {
  SurfaceFrame frame;
  Eigen::MatrixX3d rest(4, 3);
  rest << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  frame.displacement = displacement;
  frame.deformed = rest + displacement;
  frame.triangles.resize(2, 3);
  frame.triangles << 0, 1, 2, 0, 2, 3;
  return frame;
}

TEST(SurfaceError, RmsAndMaxOverTheDiagonalAreExact) {
  const SurfaceFrame reference = square(Eigen::MatrixX3d::Zero(4, 3));
  Eigen::MatrixX3d u = Eigen::MatrixX3d::Zero(4, 3);
  u.row(0) << 3.0, 4.0, 0.0;  // vertex 0 off by (3, 4, 0): distance 5
  u(2, 2) = 1.0;              // vertex 2 off by 1
  const SurfaceFrame run = square(u);
  const double diagonal = std::sqrt(2.0);
  EXPECT_DOUBLE_EQ(rest_diagonal(reference), diagonal);
  const SurfaceError error = surface_error(run, reference);  // the same surface: vertex by vertex
  EXPECT_DOUBLE_EQ(error.rms, std::sqrt((25.0 + 1.0) / 4.0) / diagonal);
  EXPECT_DOUBLE_EQ(error.max, 5.0 / diagonal);
  EXPECT_EQ(error.relative_rms, std::numeric_limits<double>::infinity());  // the reference does not move
  EXPECT_THROW(surface_error(Eigen::MatrixX3d::Zero(3, 3), reference.deformed, reference.displacement, diagonal),
               InputError);
}

TEST(SurfaceError, RelativeToTheReferencesRmsDisplacementIsExact) {
  // The reference moves every vertex by (0, 0, 2): RMS displacement 2. The run is off by
  // 1 at one vertex: RMS error 1/2, so 1/4 of the solution whatever the body's size.
  Eigen::MatrixX3d u = Eigen::MatrixX3d::Zero(4, 3);
  u.col(2).setConstant(2.0);
  const SurfaceFrame reference = square(u);
  u(3, 0) = 1.0;
  EXPECT_DOUBLE_EQ(surface_error(square(u), reference).relative_rms, 0.25);
  // On other vertices the reference's displacement is taken where they lie (linear here).
  SurfaceFrame run;
  run.displacement = Eigen::MatrixX3d::Zero(2, 3);
  run.displacement.col(2).setConstant(2.0);
  run.displacement(0, 1) = 2.0;  // off by 2 at one of two vertices: RMS error √2, relative √2 / 2
  run.deformed = run.displacement;
  run.deformed.row(0) += Eigen::RowVector3d(0.5, 0.5, 0.0);
  run.deformed.row(1) += Eigen::RowVector3d(0.25, 0.75, 0.0);
  EXPECT_NEAR(surface_error(run, reference).relative_rms, std::sqrt(2.0) / 2.0, 1e-14);
}

TEST(SurfaceError, TransfersALinearReferenceExactlyToOtherVertices) {
  // u = (x, 2y, x + y) is linear, so its interpolation on the triangles is exact.
  Eigen::MatrixX3d u(4, 3);
  u << 0, 0, 0, 1, 0, 1, 1, 2, 2, 0, 2, 1;
  const SurfaceFrame reference = square(u);
  Eigen::MatrixX3d points(3, 3);
  points << 0.25, 0.5, 0, 0.7, 0.1, 0, 0.5, 0.5, 0;
  const Eigen::MatrixX3d moved = reference_at(reference, points);
  for (int i = 0; i < 3; ++i) {
    const double x = points(i, 0), y = points(i, 1);
    EXPECT_NEAR((moved.row(i) - Eigen::RowVector3d(x + x, y + 2 * y, x + y)).norm(), 0.0, 1e-14) << i;
  }
  // A run on a finer surface with the same linear field has zero error.
  SurfaceFrame run;
  run.displacement.resize(3, 3);
  for (int i = 0; i < 3; ++i) run.displacement.row(i) << points(i, 0), 2 * points(i, 1), points(i, 0) + points(i, 1);
  run.deformed = points + run.displacement;
  EXPECT_NEAR(surface_error(run, reference).max, 0.0, 1e-14);
}

TEST(SurfaceError, ReadsTheSurfaceFramesThatRunWrites) {
  Eigen::MatrixX3d u(4, 3);
  u << 0.1, 0, 0, 0, 0.2, 0, 0, 0, 0.3, 0.4, 0.5, 0.6;
  const SurfaceFrame frame = square(u);
  UnstructuredGrid grid;
  grid.points = frame.deformed;
  grid.add_triangles(frame.triangles);
  grid.point_data.emplace_back("displacement", frame.displacement);
  const auto file = std::filesystem::temp_directory_path() / "altfem_unit_compare_surface.vtu";
  write_vtu(file, grid);
  const SurfaceFrame read = read_surface_frame(file);
  EXPECT_EQ(read.deformed, frame.deformed);
  EXPECT_EQ(read.displacement, frame.displacement);
  EXPECT_EQ(read.triangles, frame.triangles);
  std::filesystem::remove(file);
  EXPECT_THROW(read_surface_frame(file), InputError);
}

}  // namespace
}  // namespace altfem
