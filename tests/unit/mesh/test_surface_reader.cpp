#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "shared/mesh/surface_mesh.hpp"

namespace altfem {
namespace {

// Unit cube, outward (counter-clockwise seen from outside) triangles.
const double cube_vertices[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                    {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
const int cube_triangles[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                                   {3, 7, 6}, {3, 6, 2}, {0, 4, 7}, {0, 7, 3}, {1, 2, 6}, {1, 6, 5}};

std::filesystem::path write_file(const std::string& name, const std::string& text) {
  const std::filesystem::path folder = std::filesystem::path(ALTFEM_BINARY_DIR) / "tests" / "unit_mesh_files";
  std::filesystem::create_directories(folder);
  std::ofstream(folder / name, std::ios::binary) << text;
  return folder / name;
}

std::string vertex_text(int v) {
  return std::to_string(cube_vertices[v][0]) + " " + std::to_string(cube_vertices[v][1]) + " " +
         std::to_string(cube_vertices[v][2]);
}

// flip_mask bit t reverses triangle t.
std::string cube_off(unsigned flip_mask = 0) {
  std::string text = "OFF\n8 12 0\n";
  for (int v = 0; v < 8; ++v) text += vertex_text(v) + "\n";
  for (int t = 0; t < 12; ++t) {
    const int* f = cube_triangles[t];
    text += (flip_mask >> t & 1u)
                ? "3 " + std::to_string(f[0]) + " " + std::to_string(f[2]) + " " + std::to_string(f[1])
                : "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]);
    text += "\n";
  }
  return text;
}

std::string cube_obj() {
  std::string text = "# unit cube\n";
  for (int v = 0; v < 8; ++v) text += "v " + vertex_text(v) + "\n";
  for (const auto& f : cube_triangles)
    text += "f " + std::to_string(f[0] + 1) + " " + std::to_string(f[1] + 1) + " " + std::to_string(f[2] + 1) + "\n";
  return text;
}

std::string cube_stl() {
  std::string text = "solid cube\n";
  for (const auto& f : cube_triangles) {
    text += "facet normal 0 0 0\nouter loop\n";
    for (int corner = 0; corner < 3; ++corner) text += "vertex " + vertex_text(f[corner]) + "\n";
    text += "endloop\nendfacet\n";
  }
  return text + "endsolid cube\n";
}

std::string cube_ply() {
  std::string text =
      "ply\nformat ascii 1.0\nelement vertex 8\nproperty double x\nproperty double y\nproperty double z\n"
      "element face 12\nproperty list uchar int vertex_indices\nend_header\n";
  for (int v = 0; v < 8; ++v) text += vertex_text(v) + "\n";
  for (const auto& f : cube_triangles)
    text += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) + "\n";
  return text;
}

TEST(SurfaceReader, BunnyIsClosedWithItsKnownVolume) {
  std::vector<std::string> warnings;
  const SurfaceMesh bunny =
      read_surface(std::filesystem::path(ALTFEM_SOURCE_DIR) / "data/surface/bunny_npm.off", &warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_NEAR(surface_volume(bunny), 194.29, 0.01);
}

TEST(SurfaceReader, CubeReadsInEveryFormat) {
  const std::vector<std::pair<std::string, std::string>> files{
      {"cube.off", cube_off()}, {"cube.obj", cube_obj()}, {"cube.stl", cube_stl()}, {"cube.ply", cube_ply()}};
  for (const auto& [name, text] : files) {
    SCOPED_TRACE(name);
    std::vector<std::string> warnings;
    const SurfaceMesh cube = read_surface(write_file(name, text), &warnings);
    EXPECT_TRUE(warnings.empty());
    EXPECT_EQ(cube.vertices.rows(), 8);  // STL's repeated corners are merged
    EXPECT_EQ(cube.triangles.rows(), 12);
    EXPECT_NEAR(surface_volume(cube), 1.0, 1e-12);
  }
}

TEST(SurfaceReader, QuadrilateralFacesAreTriangulated) {
  const std::string text = "OFF\n8 6 0\n" + [] {
    std::string vertices;
    for (int v = 0; v < 8; ++v) vertices += vertex_text(v) + "\n";
    return vertices;
  }() + "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 3 7 6 2\n4 0 4 7 3\n4 1 2 6 5\n";
  const SurfaceMesh cube = read_surface(write_file("quad_cube.off", text));
  EXPECT_EQ(cube.triangles.rows(), 12);
  EXPECT_NEAR(surface_volume(cube), 1.0, 1e-12);
}

TEST(SurfaceReader, InwardCubeIsFlippedWithAWarning) {
  std::vector<std::string> warnings;
  const SurfaceMesh cube = read_surface(write_file("inward_cube.off", cube_off(0xfffu)), &warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("inward_cube.off: the surface was oriented inward"), std::string::npos) << warnings[0];
  EXPECT_NEAR(surface_volume(cube), 1.0, 1e-12);
}

TEST(SurfaceReader, OneFlippedFaceIsReorientedWithAWarning) {
  std::vector<std::string> warnings;
  const SurfaceMesh cube = read_surface(write_file("one_flipped_cube.off", cube_off(1u << 5)), &warnings);
  ASSERT_FALSE(warnings.empty());
  EXPECT_NE(warnings[0].find("orientations were inconsistent"), std::string::npos) << warnings[0];
  EXPECT_NEAR(surface_volume(cube), 1.0, 1e-12);
}

}  // namespace
}  // namespace altfem
