// Geometry that is thin, tiny or huge (issue #35, item 2): the common surface of a shape
// is sized by the shape, not by its thinnest feature when the shape's own planes resolve
// it, and a cube of 1 µm or 1,000 km is the unit cube scaled.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "shared/mesh/surface_mesh.hpp"
#include "shared/scene/scene.hpp"
#include "shared/scene/scene_geometry.hpp"

namespace altfem {
namespace {

SceneGeometry box_geometry(const std::string& max) {
  const Scene scene = parse_scene(R"({"geometry": {"shape": {"box": {"min": [0, 0, 0], "max": )" + max + R"(}}},
    "material": {"youngs_modulus": 1e9, "poisson_ratio": 0.3},
    "boundary_conditions": [{"type": "dirichlet", "region": {"box": {"min": [-1e7, -1e7, -1e7], "max": [0, 1e7, 1e7]}},
                             "motion": {"kind": "fixed"}}]})",
                                  "box.json");
  return load_scene_geometry(scene);
}

// The plate used to be meshed at half its thickness (48 million tetrahedra, > 4 GB,
// never finished); its planes are planes of its exact mesh, so the bounding box sizes it.
TEST(ThinGeometry, APlateOneThousandthAsThickAsWideHasASurfaceSizedByItsWidth) {
  const SceneGeometry plate =
      load_scene_geometry(load_scene(std::filesystem::path(ALTFEM_SOURCE_DIR) / "tests/cli/scenes/thin_plate.json"));
  ASSERT_TRUE(plate.shape_surface.has_value());
  const SurfaceMesh& surface = *plate.shape_surface;
  EXPECT_LT(surface.triangles.rows(), 20000);
  EXPECT_GT(surface.triangles.rows(), 1000) << "finer than the diagonal / 40 asks";
  EXPECT_NEAR(surface_volume(surface), 0.001, 1e-12);
  EXPECT_NEAR(plate.volume, 0.001, 1e-15);
}

TEST(ScaledGeometry, CubesOfOneMicrometreAndOneThousandKilometresAreTheUnitCubeScaled) {
  const SceneGeometry unit = box_geometry("[1, 1, 1]");
  for (const double side : {1e-6, 1e6}) {
    SCOPED_TRACE(side);
    const std::string corner =
        "[" + std::to_string(side) + ", " + std::to_string(side) + ", " + std::to_string(side) + "]";
    const SceneGeometry cube = box_geometry(corner);
    ASSERT_EQ(cube.shape_surface->triangles.rows(), unit.shape_surface->triangles.rows());
    EXPECT_NEAR(cube.shape_surface->vertices.norm(), side * unit.shape_surface->vertices.norm(),
                1e-12 * side * unit.shape_surface->vertices.norm());
    EXPECT_NEAR(surface_volume(*cube.shape_surface), std::pow(side, 3), 1e-12 * std::pow(side, 3));
  }
}

}  // namespace
}  // namespace altfem
