// Stiffness warping of the harmonic method (Martin et al. 2008 §6; issue #19), with MFS
// bases on every cell, each test printing its numbers:
//   - a large rigid rotation gives no force with warping (≤ 1e-10 relative), a large one
//     without it (the ghost forces of §6);
//   - the patch test under warping: a rotated affine field leaves no force on interior nodes;
//   - the twisting beam (90° twist, quasi-static, coarse grid, linear material): warped
//     harmonic stays close to fem with corotated_linear, plain linear harmonic inflates.
#include <gtest/gtest.h>

#include <cstdio>

#include "polyhedral/harmonic_method.hpp"
#include "shared/fem/method/fem_method.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/solve/time_integrator.hpp"

namespace altfem::harmonic {
namespace {

Scene with_material(Scene scene, const std::string& model) {
  for (MaterialSpec& material : scene.materials) material.model = model;
  scene.material.model = model;
  return scene;
}

// The free box with linear material on a [3, 2, 2] hex grid, MFS bases everywhere.
Scene free_box(bool warping) {
  Scene scene = load_scene(std::filesystem::path(ALTFEM_SOURCE_DIR) / "tests/unit/conformance/scenes/free_box.json");
  scene.resolved["discretization"]["harmonic"] = {
      {"convert", {{"mesh", "grid"}, {"element", "hex8"}, {"resolution", {3, 2, 2}}}},
      {"basis", "mfs"},
      {"warping", warping}};
  return with_material(scene, "linear");
}

Eigen::Matrix3d large_rotation() {
  return Eigen::AngleAxisd(1.3, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
}

// The harmonic forces of the field x ↦ (G − I) x + t, with and without warping.
struct Forces {
  Eigen::VectorXd linear, warped, nodes;
};
Forces affine_forces(const Eigen::Matrix3d& G, const Eigen::Vector3d& t) {
  Forces forces;
  for (bool warping : {false, true}) {
    const Scene scene = free_box(warping);
    const SceneGeometry geometry = load_scene_geometry(scene);
    const auto method = make_harmonic_method(scene, geometry);
    const Eigen::VectorXd u = method->interpolate(
        [&](const Eigen::Vector3d& x) -> Eigen::Vector3d { return (G - Eigen::Matrix3d::Identity()) * x + t; });
    method->discretization().gradient(u, warping ? forces.warped : forces.linear);
    forces.nodes = method->interpolate([](const Eigen::Vector3d& x) { return x; });
  }
  return forces;
}

TEST(HarmonicWarping, RigidRotationGivesNoForce) {
  const Forces forces = affine_forces(large_rotation(), {0.2, -0.1, 0.3});
  std::printf("[ rigid    ] MFS bases, rotation by 1.3 rad   |f| linear %.3e   |f| warped %.3e   relative %.2e\n",
              forces.linear.norm(), forces.warped.norm(), forces.warped.norm() / forces.linear.norm());
  EXPECT_GT(forces.linear.norm(), 1e2);
  EXPECT_LT(forces.warped.norm(), 1e-10 * forces.linear.norm());
}

TEST(HarmonicWarping, PatchTestUnderARotatedAffineField) {
  Eigen::Matrix3d stretch;
  stretch << 1.02, 0.01, -0.005, 0.004, 0.99, 0.006, -0.003, 0.008, 1.015;
  const Forces forces = affine_forces(large_rotation() * stretch, {0.1, 0.2, -0.3});
  double interior = 0;
  int interior_nodes = 0;
  for (Eigen::Index node = 0; node < forces.nodes.size() / 3; ++node) {
    const Eigen::Array3d x = forces.nodes.segment<3>(3 * node);
    if ((x > 1e-9).all() && (x < Eigen::Array3d(2, 1, 1) - 1e-9).all())
      interior = std::max(interior, forces.warped.segment<3>(3 * node).norm()), ++interior_nodes;
  }
  const double scale = forces.warped.cwiseAbs().maxCoeff();
  std::printf("[ patch    ] warped, rotated affine field   %d interior nodes   max interior |f| / max |f| %.2e\n",
              interior_nodes, interior / scale);
  ASSERT_GT(interior_nodes, 0);
  EXPECT_LT(interior, 1e-10 * scale);
}

// The twisting beam's free end turned by 90° (t = 0.5 s) in 10 quasi-static load steps on a
// [10, 2, 2] hex grid: the embedded surface's displacement and the mean radius of its
// vertices at mid-length relative to the rest radius.
struct Twist {
  Eigen::MatrixXd surface_displacement;
  double radius_ratio = 0;
  int newton_iterations = 0;  // over the 10 load steps
};
Twist twist(const Scene& scene, const MethodFactory& factory) {
  const SceneGeometry geometry = load_scene_geometry(scene);
  const auto method = factory(scene, geometry);
  const Discretization& discretization = method->discretization();
  const auto solver = make_linear_solver({});
  IntegratorOptions options;
  options.kind = IntegrationScheme::static_equilibrium;
  TimeIntegrator integrator(discretization, *solver, options);
  State state{Eigen::VectorXd::Zero(discretization.dof_count()), Eigen::VectorXd::Zero(discretization.dof_count())};
  int newton_iterations = 0;
  for (int step = 1; step <= 10; ++step) {
    state.time = 0.05 * step;
    integrator.apply_constraints(state);
    newton_iterations += integrator.step(state).newton_iterations;
  }
  Twist result;
  result.newton_iterations = newton_iterations;
  result.surface_displacement = method->embedded_displacement(state.displacement);
  const Eigen::MatrixXd& rest = method->embedded_surface().vertices;
  double ratio = 0;
  int count = 0;
  for (Eigen::Index v = 0; v < rest.rows(); ++v)
    if (std::abs(rest(v, 0) - 0.5) < 1e-9) {
      const Eigen::RowVector3d moved = rest.row(v) + result.surface_displacement.row(v);
      ratio += moved.tail<2>().norm() / rest.row(v).tail<2>().norm(), ++count;
    }
  result.radius_ratio = ratio / count;
  return result;
}

TEST(HarmonicWarping, TwistingBeamStaysCloseToCorotatedFem) {
  const Scene base = load_scene(std::filesystem::path(ALTFEM_SOURCE_DIR) / "scenes/twisting_beam.json");
  Scene fem = with_material(base, "corotated_linear");
  fem.resolved["discretization"]["fem"] = {{"element", "hex8"}, {"mesh", "grid"}, {"resolution", {10, 2, 2}}};
  const Twist reference = twist(fem, make_fem_method);
  std::printf(
      "[ twist    ] 90° twist, [10,2,2] hex grid      mid-length radius / rest   |u − u_fem| / |u_fem| (surface)   "
      "Newton iterations\n");
  std::printf("[ twist    ] fem hex8, corotated_linear        %8.4f   %34s %d\n", reference.radius_ratio, "",
              reference.newton_iterations);
  double error[2] = {0, 0};
  for (bool warping : {false, true}) {
    Scene harmonic = with_material(base, "linear");
    harmonic.resolved["discretization"]["harmonic"] = {
        {"convert", {{"mesh", "grid"}, {"element", "hex8"}, {"resolution", {10, 2, 2}}}},
        {"basis", "mfs"},
        {"warping", warping}};
    const Twist result = twist(harmonic, make_harmonic_method);
    ASSERT_EQ(result.surface_displacement.rows(), reference.surface_displacement.rows());
    error[warping] =
        (result.surface_displacement - reference.surface_displacement).norm() / reference.surface_displacement.norm();
    std::printf("[ twist    ] harmonic mfs, linear, warping %-5s %8.4f   %34.3e %d\n", warping ? "on" : "off",
                result.radius_ratio, error[warping], result.newton_iterations);
    if (warping) EXPECT_NEAR(result.radius_ratio, reference.radius_ratio, 0.02);
    else EXPECT_GT(result.radius_ratio, reference.radius_ratio + 0.05);  // linear strain inflates a twist
  }
  EXPECT_LT(error[1], 0.05);
  EXPECT_GT(error[0], 3 * error[1]);
}

}  // namespace
}  // namespace altfem::harmonic
