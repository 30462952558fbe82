// Stiffness warping under large rotation (Kaufmann et al. 2009 §6): the shipped
// cantilever (1 × 0.1 × 0.1 m, clamped at x = 0, its own weight) softened to E = 3 MPa,
// so that linear theory puts the tip 0.49 m down — a rotation of the tip of about 35°.
// Linear DG keeps the beam's length and stretches it; warped DG (k = 2, 20 × 2 × 2 cells)
// follows fem's corotated linear material (Hex20, same grid): the surface difference is
// printed and checked, as are the volume change and the tip's pull-back along x.
#include <gtest/gtest.h>

#include <cmath>

#include "dg/dg_method.hpp"
#include "shared/fem/method/fem_method.hpp"
#include "shared/mesh/surface_mesh.hpp"
#include "shared/scene/scene_override.hpp"
#include "shared/simulation/simulation.hpp"
#include "shared/solve/time_integrator.hpp"
#include "tests/support/static_solve.hpp"

namespace altfem::dg {
namespace {

test::StaticSurface run(const MethodFactory& factory, std::vector<std::string> assignments) {
  assignments.push_back("/material/youngs_modulus=3e6");
  return test::static_surface(std::filesystem::path(ALTFEM_SOURCE_DIR) / "scenes/cantilever.json", factory,
                              assignments);
}

// RMS over the vertices of |u − u_reference|, relative to the bounding-box diagonal
// (the project's surface error, docs/conventions.md "Metrics").
double surface_difference(const test::StaticSurface& surface, const test::StaticSurface& reference) {
  const double diagonal = (surface.vertices.colwise().maxCoeff() - surface.vertices.colwise().minCoeff()).norm();
  return std::sqrt((surface.displacement - reference.displacement).rowwise().squaredNorm().mean()) / diagonal;
}

double volume_ratio(const test::StaticSurface& surface) {
  SurfaceMesh rest, deformed;
  rest.vertices = surface.vertices;
  rest.triangles = deformed.triangles = surface.triangles;
  deformed.vertices = surface.vertices + surface.displacement;
  return surface_volume(deformed) / surface_volume(rest);
}

TEST(DgWarpingCantilever, WarpedDgFollowsTheCorotatedFemWhileLinearDgInflates) {
  const test::StaticSurface reference = run(make_fem_method, {"/material/model=corotated_linear"});
  const test::StaticSurface linear = run(make_dg_method, {});
  const test::StaticSurface warped = run(make_dg_method, {"/discretization/dg/warping=true"});
  ASSERT_EQ(linear.vertices, reference.vertices);  // the box's common surface
  std::printf("  %-26s %11s %11s %13s %13s\n", "run", "tip z (m)", "tip x (m)", "volume ratio", "vs corotated");
  const auto row = [&](const char* name, const test::StaticSurface& surface) {
    std::printf("  %-26s %11.4f %11.4f %13.4f %13.3e\n", name, test::mean_on_plane(surface, 0, 1.0, 2, 1e-9),
                test::mean_on_plane(surface, 0, 1.0, 0, 1e-9), volume_ratio(surface),
                surface_difference(surface, reference));
  };
  row("fem Hex20 corotated", reference);
  row("dg k=2 linear", linear);
  row("dg k=2 warped", warped);
  EXPECT_LT(surface_difference(warped, reference), 0.1 * surface_difference(linear, reference));
  EXPECT_LT(surface_difference(warped, reference), 0.01);
  EXPECT_GT(volume_ratio(linear), 1.02);  // linear strain of a rotation: a spurious stretch
  EXPECT_NEAR(volume_ratio(warped), 1.0, 0.01);
}

// A moving condition with warping: the shipped twisting beam (1 × 0.2 × 0.2 m, E = 1 MPa,
// ν = 0.4) made linear and static, its end at x = 1 turned by 90° (the rotating wall's
// data enters Nitsche's terms rotated with each boundary element). Warped DG (k = 2,
// 10 × 2 × 2 cells) follows fem's corotated linear Hex20 on the same grid; linear DG
// reads the turn as strain and inflates the beam (volume ratio printed).
TEST(DgWarpingCantilever, WarpedDgTwistsLikeTheCorotatedFem) {
  const auto twist = [](const MethodFactory& factory, const std::vector<std::string>& specific) {
    std::vector<std::string> assignments;
    for (const char* assignment :
         {"/material/youngs_modulus=1e6", "/time={\"static\": true}",
          "/boundary_conditions/1/motion/angular_velocity=1.5707963267948966",
          "/discretization/fem={\"element\": \"hex20\", \"mesh\": \"grid\", \"resolution\": [10, 2, 2]}",
          "/discretization/dg={\"degree\": 2, \"resolution\": [10, 2, 2]}"})
      assignments.emplace_back(assignment);
    assignments.insert(assignments.end(), specific.begin(), specific.end());
    return test::static_surface(std::filesystem::path(ALTFEM_SOURCE_DIR) / "scenes/twisting_beam.json", factory,
                                assignments);
  };
  const test::StaticSurface reference = twist(make_fem_method, {"/material/model=corotated_linear"});
  const test::StaticSurface linear = twist(make_dg_method, {"/material/model=linear"});
  const test::StaticSurface warped =
      twist(make_dg_method, {"/material/model=linear", "/discretization/dg/warping=true"});
  std::printf("  %-22s %13s %13s\n", "run", "volume ratio", "vs corotated");
  const auto row = [&](const char* name, const test::StaticSurface& surface) {
    std::printf("  %-22s %13.4f %13.3e\n", name, volume_ratio(surface), surface_difference(surface, reference));
  };
  row("fem Hex20 corotated", reference);
  row("dg k=2 linear", linear);
  row("dg k=2 warped", warped);
  EXPECT_LT(surface_difference(warped, reference), 0.1 * surface_difference(linear, reference));
  EXPECT_NEAR(volume_ratio(warped), volume_ratio(reference), 0.01);
  EXPECT_GT(volume_ratio(linear), volume_ratio(reference) + 0.02);
}

// The time integrators take the warped forces (hessian(): R K Rᵀ, rotations frozen):
// backward Euler by Newton to its tolerance, and the semi-implicit step (one Newton
// iteration, Kaufmann et al.'s own scheme, §4.3 and §6.3) on a coarse softened cantilever
// released from rest; both fall the same way, and within 5% of each other at t = 0.1 s.
TEST(DgWarpingCantilever, BackwardEulerAndSemiImplicitRunWithWarping) {
  Eigen::Vector3d tip[2];
  for (IntegrationScheme scheme : {IntegrationScheme::backward_euler, IntegrationScheme::semi_implicit}) {
    const std::vector<SceneOverride> overrides{parse_scene_override("/material/youngs_modulus=3e6"),
                                               parse_scene_override("/discretization/dg/warping=true"),
                                               parse_scene_override("/discretization/dg/resolution=[10,1,1]")};
    const Scene scene = load_scene(std::filesystem::path(ALTFEM_SOURCE_DIR) / "scenes/cantilever.json", overrides);
    const SceneGeometry geometry = load_scene_geometry(scene);
    const auto method = make_dg_method(scene, geometry);
    const auto solver = make_linear_solver({});
    IntegratorOptions options;
    options.kind = scheme;
    options.time_step = 0.005;
    options.gravity = scene.gravity;
    TimeIntegrator integrator(method->discretization(), *solver, options);
    const int dofs = method->discretization().dof_count();
    State state{Eigen::VectorXd::Zero(dofs), Eigen::VectorXd::Zero(dofs)};
    int newton_iterations = 0;
    for (int step = 0; step < 20; ++step) newton_iterations += integrator.step(state).newton_iterations;
    const Eigen::MatrixXd displacement = method->embedded_displacement(state.displacement);
    const Eigen::MatrixXd& vertices = method->embedded_surface().vertices;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    int count = 0;
    for (Eigen::Index v = 0; v < vertices.rows(); ++v)
      if (std::abs(vertices(v, 0) - 1.0) < 1e-9) sum += displacement.row(v).transpose(), ++count;
    tip[scheme == IntegrationScheme::semi_implicit] = sum / count;
    std::printf("  %-15s tip at t = 0.1 s: (%.4f, %.4f, %.4f) m, %d Newton iterations in 20 steps\n",
                std::string(integration_scheme_name(scheme)).c_str(), sum.x() / count, sum.y() / count, sum.z() / count,
                newton_iterations);
    EXPECT_TRUE(state.displacement.allFinite());
    EXPECT_LT(tip[scheme == IntegrationScheme::semi_implicit].z(), -0.01);
  }
  EXPECT_LT((tip[0] - tip[1]).norm(), 0.05 * tip[0].norm());
}

}  // namespace
}  // namespace altfem::dg
