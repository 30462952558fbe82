// The conformance suite's properties (test_conformance.cpp) on the mesh a cut leaves
// (issue #33): the free box cut through its cells by a tilted plane at t = 0 falls in two
// pieces, which every method rebuilds with (dg's pieces, harmonic's new MFS cells, fcm's
// and fem's node copies). The material's volume is kept; the six rigid motions still give
// zero force and span part of the stiffness's kernel (which now holds each piece's); an
// affine field's energy is the integrated volume times ψ(G) and its virtual work P(G) : B
// (the patch test: the cut cells' rules integrate constants); and it is embedded exactly
// on the cut surface, at the points where its vertices on the cut read their own side.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <memory>

#include "app/method_registry.hpp"
#include "shared/material/material.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/scene/scene_override.hpp"
#include "shared/simulation/rigid_motion.hpp"
#include "shared/simulation/simulation.hpp"
#include "tests/unit/conformance/conformance_measures.hpp"

namespace altfem {
namespace {

using test::small_strain;

// The free box of the conformance suite cut by the plane through (0.9, 0.5, 0.5) normal
// to (1, 0.3, 0.2), which crosses cells of every method's grid.
struct CutBox {
  Scene scene;
  SceneGeometry geometry;
  std::unique_ptr<Simulation> simulation;
  std::unique_ptr<Material> material;
  EventRecord record;

  explicit CutBox(const std::string& method_name) {
    scene = load_scene(std::filesystem::path(ALTFEM_SOURCE_DIR) / "tests/unit/conformance/scenes/free_box.json",
                       {parse_scene_override("events=[{\"time\": 0, \"cut\": {\"plane\": {\"point\": [0.9, 0.5, 0.5], "
                                             "\"normal\": [1, 0.3, 0.2]}}}]")});
    geometry = load_scene_geometry(scene);
    const MethodDescription& description = cli::find_method(method_name);
    simulation = std::make_unique<Simulation>(scene, geometry, method_name, description.factory, description.rebuild);
    record = simulation->apply(scene.events.at(0));
    const MaterialSpec& spec = scene.material;
    material =
        make_material(*material_model_from_name(spec.model), spec.youngs_modulus, spec.poisson_ratio, spec.density);
  }
  const MethodInstance& method() const { return simulation->method(); }
  Eigen::VectorXd interpolate(const Eigen::Matrix3d& A, const Eigen::Vector3d& b = Eigen::Vector3d::Zero()) const {
    return method().interpolate([&](const Eigen::Vector3d& x) -> Eigen::Vector3d { return A * x + b; });
  }
  Eigen::VectorXd gradient(const Eigen::VectorXd& u) const { return test::internal_force(method(), u); }
};

class ConformanceAfterACut : public ::testing::TestWithParam<std::string> {};

TEST_P(ConformanceAfterACut, TheMaterialsVolumeIsKept) {
  const CutBox box(GetParam());
  EXPECT_GT(box.record.dofs_after, box.record.dofs_before);  // the cut copied nodes or split cells
  EXPECT_EQ(box.record.facts["surface"]["pieces_left_whole"], 0);
  ASSERT_TRUE(box.method().volume().has_value());
  EXPECT_NEAR(*box.method().volume(), box.geometry.volume, 1e-12 * box.geometry.volume);
}

TEST_P(ConformanceAfterACut, RigidMotionsGiveZeroForceAndLieInTheKernel) {
  const CutBox box(GetParam());
  const double scale = box.gradient(box.interpolate(small_strain())).cwiseAbs().maxCoeff();
  ASSERT_GT(scale, 0);
  EXPECT_LT(box.gradient(box.interpolate(Eigen::Matrix3d::Zero(), {0.3, -0.2, 0.5})).cwiseAbs().maxCoeff(),
            1e-12 * scale);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, -1).normalized()).toRotationMatrix();
  EXPECT_LT(box.gradient(box.interpolate(R - Eigen::Matrix3d::Identity(), {0.1, 0, 0})).cwiseAbs().maxCoeff(),
            1e-10 * scale);
  const Discretization& discretization = box.method().discretization();
  const Eigen::MatrixXd modes = rigid_body_modes(box.method());
  Eigen::SparseMatrix<double> stiffness = discretization.hessian_pattern();
  discretization.hessian(Eigen::VectorXd::Zero(discretization.dof_count()), stiffness, false);
  const Eigen::VectorXd strain = box.interpolate(small_strain());
  const double stiffness_scale = (stiffness * strain).norm() / strain.norm();
  for (int mode = 0; mode < 6; ++mode)
    EXPECT_LT((stiffness * modes.col(mode)).norm(), 1e-10 * stiffness_scale * modes.col(mode).norm())
        << "mode " << mode;
}

TEST_P(ConformanceAfterACut, PatchTestGivesTheExactConstantStress) {
  const CutBox box(GetParam());
  const Eigen::Matrix3d G = Eigen::Matrix3d::Identity() + small_strain();
  Eigen::Matrix3d B;
  B << 0.3, -0.1, 0.2, 0.05, 0.4, -0.3, 0.1, 0.2, -0.2;
  const Eigen::VectorXd u = box.interpolate(G - Eigen::Matrix3d::Identity(), {0.01, 0.02, 0.03});
  const Eigen::VectorXd v = box.interpolate(B);
  const double V = test::integrated_volume(box.method(), box.scene.material.density);
  const double energy = V * box.material->energy(G);
  const double work = V * (box.material->pk1(G).array() * B.array()).sum();
  EXPECT_NEAR(box.method().discretization().energy(u), energy, 1e-10 * std::abs(energy));
  EXPECT_NEAR(box.gradient(u).dot(v), work, 1e-10 * std::abs(work));
}

// The cut's vertices read the field a hair inside their own side (SurfaceMesh::
// embedding_offsets, under 10⁻⁶ of the box here): there the affine field is exact.
TEST_P(ConformanceAfterACut, AffineFieldIsEmbeddedExactlyOnTheCutSurface) {
  const CutBox box(GetParam());
  const Eigen::Matrix3d A = small_strain();
  const Eigen::Vector3d b(0.1, -0.2, 0.3);
  const Eigen::MatrixXd moved = box.method().embedded_displacement(box.interpolate(A, b));
  const SurfaceMesh& surface = box.method().embedded_surface();
  ASSERT_GT(surface.vertices.rows(), 8);  // the cut's vertices and caps
  ASSERT_EQ(moved.rows(), surface.vertices.rows());
  const Eigen::MatrixXd points = embedding_points(surface);
  EXPECT_LT((points - surface.vertices).cwiseAbs().maxCoeff(), 1e-6);
  const Eigen::MatrixXd expected = (points * A.transpose()).rowwise() + b.transpose();
  EXPECT_LT((moved - expected).cwiseAbs().maxCoeff(), 1e-12);
}

std::vector<std::string> cutting_methods() {
  std::vector<std::string> names;
  for (const auto& method : cli::registered_methods())
    if (method.rebuild) names.emplace_back(method.scene_block.name);
  return names;
}

INSTANTIATE_TEST_SUITE_P(EveryMethod, ConformanceAfterACut, ::testing::ValuesIn(cutting_methods()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace altfem
