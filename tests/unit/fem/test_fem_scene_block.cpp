// The `fem` block of docs/scene-schema.md: defaults from the geometry, resolved by the
// method itself (shared/fem/fem_scene_block.hpp), not by shared/scene.
#include <gtest/gtest.h>

#include "shared/common/error.hpp"
#include "shared/fem/fem_scene_block.hpp"

namespace altfem {
namespace {

Scene box_scene(const std::string& max, const std::string& fem_block) {
  return parse_scene(R"({"geometry": {"shape": {"box": {"min": [0, 0, 0], "max": )" + max +
                         R"(}}}, "material": {"youngs_modulus": 1, "poisson_ratio": 0},
                         "discretization": {"fem": )" +
                         fem_block + "}}",
                     "grid.json");
}

TEST(FemSceneBlock, BoxWithoutOptionsGetsAStructuredTet10Grid) {
  const Scene scene = box_scene("[2, 2, 2]", "{}");
  const nlohmann::json fem = resolve_method_block(scene, fem_scene_block());
  EXPECT_EQ(fem["element"], "tet10");
  EXPECT_EQ(fem["mesh"], "grid");
  EXPECT_EQ(fem["resolution"], nlohmann::json({4, 4, 4}));
  EXPECT_EQ(fem["quadrature_order"], 4);
  EXPECT_EQ(fem["curved"], false);
  EXPECT_FALSE(fem.contains("max_cell_size"));
}

TEST(FemSceneBlock, GridResolutionFollowsTheAspect) {
  const auto resolution = [](const std::string& max, const std::string& element) {
    const FemSpec fem = fem_spec(box_scene(max, R"({"element": ")" + element + R"("})"));
    EXPECT_EQ(fem.mesh, FemMeshKind::grid);
    return fem.resolution;
  };
  EXPECT_EQ(resolution("[1, 1, 1]", "hex8"), Eigen::Vector3i(4, 4, 4));
  EXPECT_EQ(resolution("[1, 0.1, 0.1]", "hex20"), Eigen::Vector3i(20, 2, 2));
  EXPECT_EQ(resolution("[1, 1, 0.01]", "hex27"), Eigen::Vector3i(32, 32, 2));
}

TEST(FemSceneBlock, QuadratureOrderDefaultsToTwiceTheDegreeAndSevenForHex27) {
  EXPECT_EQ(fem_spec(box_scene("[1, 1, 1]", R"({"element": "hex27"})")).quadrature_order, 7);
  EXPECT_EQ(fem_spec(box_scene("[1, 1, 1]", R"({"element": "hex20"})")).quadrature_order, 4);
  EXPECT_EQ(fem_spec(box_scene("[1, 1, 1]", R"({"element": "tet20"})")).quadrature_order, 6);
  EXPECT_EQ(fem_spec(box_scene("[1, 1, 1]", R"({"element": "tet4"})")).quadrature_order, 2);
}

TEST(FemSceneBlock, ResolvingTwiceChangesNothing) {
  Scene scene = box_scene("[1, 0.1, 0.1]", R"({"element": "hex20"})");
  const nlohmann::json once = resolve_method_block(scene, fem_scene_block());
  scene.resolved["discretization"]["fem"] = once;
  EXPECT_EQ(resolve_method_block(scene, fem_scene_block()), once);
}

TEST(FemSceneBlock, SurfaceCellSizeWaitsForTheSurface) {
  const Scene scene = parse_scene(R"({"geometry": {"surface": "thing.off"},
                                      "material": {"youngs_modulus": 1, "poisson_ratio": 0}})",
                                  "/tmp/surface.json");
  const FemSpec fem = fem_spec(scene);
  EXPECT_EQ(fem.mesh, FemMeshKind::tetrahedralize);
  EXPECT_FALSE(fem.max_cell_size.has_value());
  const Eigen::AlignedBox3d bounds(Eigen::Vector3d::Zero(), Eigen::Vector3d(3, 4, 0));
  EXPECT_DOUBLE_EQ(fem_max_cell_size(fem, bounds), 5.0 / 15.0);
}

TEST(FemSceneBlock, BadCombinationsNameTheKey) {
  const auto message = [](const std::string& block) {
    try {
      (void)fem_spec(box_scene("[1, 1, 1]", block));
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(R"({"mesh": "tetrahedralize", "element": "hex8"})"),
            "grid.json: /discretization/fem/element: 'tetrahedralize' needs a tet element, got \"hex8\"");
  EXPECT_EQ(message(R"({"mesh": "grid", "max_cell_size": 0.1})"),
            "grid.json: /discretization/fem/max_cell_size: applies only to mesh 'tetrahedralize', got mesh 'grid'");
  EXPECT_NE(message(R"({"elemnt": "hex8"})").find("did you mean 'element'"), std::string::npos);
}

// A grid over a shape built of boxes (an L: two boxes) keeps the cells inside it, so each
// of the shape's planes must be a plane of the grid, and its resolution is not guessed.
TEST(FemSceneBlock, AGridOnAShapeBuiltOfBoxesNeedsPlanesOnItsFaces) {
  const auto message = [](const std::string& block) {
    try {
      (void)fem_spec(parse_scene(R"({"geometry": {"shape": {"union": [
                                       {"box": {"min": [0, 0, 0], "max": [1, 0.5, 0.25]}},
                                       {"box": {"min": [0, 0, 0], "max": [0.5, 1, 0.25]}}]}},
                                     "material": {"youngs_modulus": 1, "poisson_ratio": 0},
                                     "discretization": {"fem": )" +
                                     block + "}}",
                                 "l.json"));
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(R"({"mesh": "grid", "element": "hex8", "resolution": [4, 2, 1]})"), "no error");
  EXPECT_EQ(message(R"({"mesh": "grid", "element": "hex8", "resolution": [3, 2, 1]})"),
            "l.json: /discretization/fem/resolution: must put a grid plane on each face of the shape: x = 0.5 falls "
            "between the planes 0 + k · 0.333333");
  EXPECT_EQ(message(R"({"mesh": "grid", "element": "hex8"})"),
            "l.json: /discretization/fem/resolution: is required for 'grid' on a shape built of boxes: cells whose "
            "faces hold the shape's faces");
}

}  // namespace
}  // namespace altfem
