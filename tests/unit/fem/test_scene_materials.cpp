// Material regions (docs/scene-schema.md, "Material"): elements take the first material
// whose region holds their centroid, the rest the first material.
#include <gtest/gtest.h>

#include "shared/common/error.hpp"
#include "shared/fem/method/fem_method.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/simulation/scene_materials.hpp"

namespace altfem {
namespace {

// MFEM example 17's beam: 8 × 1 × 1, the first half one material, the rest another.
Scene two_material_beam(const std::string& second_region) {
  return parse_scene(R"({
    "geometry": { "shape": { "box": { "min": [0, 0, 0], "max": [8, 1, 1] } } },
    "materials": [
      { "model": "linear", "youngs_modulus": 130, "poisson_ratio": 0.3, "density": 1000 },
      { "model": "linear", "youngs_modulus": 2.6, "poisson_ratio": 0.3, "density": 250,
        "region": )" + second_region +
                         R"( } ],
    "discretization": { "fem": { "element": "hex8", "resolution": [8, 2, 2] } } })",
                     "beam.json");
}

TEST(SceneMaterials, ElementsTakeTheMaterialOfTheirCentroid) {
  const Scene scene = two_material_beam(R"({ "box": { "min": [4, -1, -1], "max": [9, 2, 2] } })");
  ASSERT_EQ(scene.materials.size(), 2u);
  EXPECT_EQ(scene.material.youngs_modulus, 130);
  const SceneMaterials materials(scene);
  EXPECT_EQ(materials.id_at({1, 0.5, 0.5}), 0);
  EXPECT_EQ(materials.id_at({5, 0.5, 0.5}), 1);
  // The mass of the discretized beam is ρ₁ V₁ + ρ₂ V₂ exactly.
  const SceneGeometry geometry = load_scene_geometry(scene);
  const auto method = make_fem_method(scene, geometry);
  const Eigen::VectorXd load = method->discretization().body_force(Eigen::Vector3d::UnitX());
  EXPECT_NEAR(load.sum(), 1000 * 4 + 250 * 4, 1e-9);
}

TEST(SceneMaterials, ARegionThatHoldsNoElementIsBadInput) {
  const Scene scene = two_material_beam(R"({ "sphere": { "centre": [20, 0, 0], "radius": 1 } })");
  const SceneGeometry geometry = load_scene_geometry(scene);
  try {
    (void)make_fem_method(scene, geometry);
    FAIL() << "accepted a region that selects nothing";
  } catch (const InputError& error) {
    EXPECT_NE(
        std::string(error.what()).find("beam.json: /materials/1/region: expected a region that holds the centroid"),
        std::string::npos)
        << error.what();
  }
}

TEST(SceneMaterials, MaterialAndMaterialsAreExclusive) {
  EXPECT_THROW(parse_scene(R"({"geometry": {"shape": {"box": {"min": [0, 0, 0], "max": [1, 1, 1]}}},
                               "material": {"youngs_modulus": 1, "poisson_ratio": 0},
                               "materials": [{"youngs_modulus": 1, "poisson_ratio": 0}]})",
                           "both.json"),
               InputError);
}

}  // namespace
}  // namespace altfem
