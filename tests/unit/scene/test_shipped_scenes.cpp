// Every scene in scenes/ validates and its geometry loads.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "shared/fem/fem_scene_block.hpp"
#include "shared/scene/scene.hpp"
#include "shared/scene/scene_geometry.hpp"

namespace altfem {
namespace {

const std::filesystem::path scenes = std::filesystem::path(ALTFEM_SOURCE_DIR) / "scenes";

TEST(ShippedScenes, EveryOneLoadsWithItsGeometry) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(scenes)) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    const Scene scene = load_scene(entry.path());
    const SceneGeometry geometry = load_scene_geometry(scene);
    EXPECT_EQ(scene.name, entry.path().stem().string());
    EXPECT_GT(geometry.volume, 0.0);
    EXPECT_FALSE(geometry.bounds.isEmpty());
    // Held by a condition, or set moving (the spinning body floats free).
    EXPECT_TRUE(!scene.dirichlet.empty() || scene.initial.angular_velocity.norm() > 0);
    ++count;
  }
  EXPECT_GE(count, 6);
}

TEST(ShippedScenes, CantileverIsExactlyTheSpecifiedBeam) {
  const Scene scene = load_scene(scenes / "cantilever.json");
  const SceneGeometry geometry = load_scene_geometry(scene);
  EXPECT_EQ(scene.geometry.kind, GeometryKind::shape);
  EXPECT_DOUBLE_EQ(geometry.volume, 1.0 * 0.1 * 0.1);
  EXPECT_TRUE(geometry.bounds.min().isApprox(Eigen::Vector3d(0, 0, 0)));
  EXPECT_TRUE(geometry.bounds.max().isApprox(Eigen::Vector3d(1, 0.1, 0.1)));
  EXPECT_EQ(scene.material.model, "linear");
  EXPECT_EQ(scene.material.youngs_modulus, 1e9);
  EXPECT_EQ(scene.material.poisson_ratio, 0.3);
  EXPECT_EQ(scene.material.density, 1000.0);
  EXPECT_EQ(scene.gravity, Eigen::Vector3d(0, 0, -9.81));
  EXPECT_TRUE(scene.time.is_static);
  const FemSpec fem = fem_spec(scene);
  EXPECT_EQ(fem.element, ElementType::hex20);
  EXPECT_EQ(fem.mesh, FemMeshKind::grid);
  EXPECT_EQ(fem.resolution, Eigen::Vector3i(20, 2, 2));
  EXPECT_EQ(fem.quadrature_order, 4);
  ASSERT_EQ(scene.dirichlet.size(), 1u);
  const double tolerance = region_tolerance(geometry.bounds);
  EXPECT_TRUE(scene.dirichlet[0].region.contains({0, 0.05, 0.05}, tolerance));
  EXPECT_FALSE(scene.dirichlet[0].region.contains({0.05, 0.05, 0.05}, tolerance));
}

TEST(ShippedScenes, BunnyIsScaledToMetresAndFixedAtItsBase) {
  const Scene scene = load_scene(scenes / "bunny.json");
  const SceneGeometry geometry = load_scene_geometry(scene);
  ASSERT_TRUE(geometry.surface.has_value());
  EXPECT_NEAR(geometry.bounds.sizes().y(), 0.0966, 1e-3);
  EXPECT_NEAR(geometry.volume, 194.29e-6, 0.01e-6);  // data/README.md: 194.29 in model units
  EXPECT_TRUE(scene.geometry.file.is_absolute());
  const FemSpec fem = fem_spec(scene);
  EXPECT_FALSE(fem.max_cell_size.has_value());
  EXPECT_NEAR(fem_max_cell_size(fem, geometry.bounds), geometry.bounds.diagonal().norm() / 15, 1e-15);
  int fixed = 0;
  for (Eigen::Index i = 0; i < geometry.surface->vertices.rows(); ++i)
    fixed += scene.dirichlet[0].region.contains(geometry.surface->vertices.row(i).transpose(), 0.0);
  EXPECT_GT(fixed, 0);
  EXPECT_LT(fixed, geometry.surface->vertices.rows() / 4);
}

TEST(ShippedScenes, HollowCylinderVolumeIsExact) {
  const Scene scene = load_scene(scenes / "hollow_cylinder.json");
  const SceneGeometry geometry = load_scene_geometry(scene);
  EXPECT_NEAR(geometry.volume, std::numbers::pi * (0.1 * 0.1 - 0.07 * 0.07) * 0.5, 1e-15);
  EXPECT_FALSE(scene.time.is_static);
  EXPECT_EQ(scene.time.steps, 30);
  EXPECT_EQ(scene.dirichlet[1].motion.kind, MotionKind::rotate);
}

TEST(ShippedScenes, CubeMeshIsReadFromTheFile) {
  const Scene scene = load_scene(scenes / "cube_msh.json");
  const SceneGeometry geometry = load_scene_geometry(scene);
  ASSERT_TRUE(geometry.mesh.has_value());
  EXPECT_EQ(geometry.mesh->element_type, ElementType::tet10);
  EXPECT_NEAR(geometry.volume, 1.0, 1e-12);
  EXPECT_EQ(fem_spec(scene).mesh, FemMeshKind::file);
  EXPECT_EQ(fem_spec(scene).element, ElementType::tet10);  // the file's, as the scene names none
  EXPECT_EQ(scene.dirichlet[1].components, (std::array<bool, 3>{false, false, true}));
}

}  // namespace
}  // namespace altfem
