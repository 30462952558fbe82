// A clamped cantilever under its own weight against Timoshenko beam theory.
//
// Beam 1 × 0.1 × 0.1 m, E = 1e9 Pa, ν = 0.3, ρ = 1000 kg/m³, g = 9.81 m/s² along −z,
// clamped (all components) at x = 0, linear elasticity, Hex20 [40, 4, 4].
// Uniform load q = ρ g A = 98.1 N/m, I = b h³ / 12 = 8.333e-6 m⁴, G = E / (2(1 + ν)),
// shear coefficient κ = 5/6 (rectangle):
//   δ = q L⁴ / (8 E I) + q L² / (2 κ G A) = 1.4715e-3 + 1.530e-5 = 1.4868e-3 m.
// The tip deflection is the mean z-displacement of the nodes of the free end face.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "shared/fem/lagrange_discretization.hpp"
#include "shared/solve/time_integrator.hpp"
#include "tests/unit/fem/test_meshes.hpp"

namespace altfem {
namespace {

TEST(Cantilever, TipDeflectionWithinTwoPercentOfTimoshenko) {
  const auto start = std::chrono::steady_clock::now();
  constexpr double length = 1.0, width = 0.1, youngs_modulus = 1e9, poisson_ratio = 0.3, density = 1000, g = 9.81;
  const double area = width * width, inertia = width * width * width * width / 12;
  const double shear_modulus = youngs_modulus / (2 * (1 + poisson_ratio)), kappa = 5.0 / 6.0;
  const double q = density * g * area;
  const double bending = q * std::pow(length, 4) / (8 * youngs_modulus * inertia);
  const double shear = q * length * length / (2 * kappa * shear_modulus * area);
  const double timoshenko = bending + shear;

  const Eigen::AlignedBox3d beam(Eigen::Vector3d(0, -width / 2, -width / 2),
                                 Eigen::Vector3d(length, width / 2, width / 2));
  DirichletCondition clamp;
  clamp.region.box = Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(0, 1, 1));
  clamp.pointer = "/boundary_conditions/0";
  const auto material = make_material(MaterialModel::linear, youngs_modulus, poisson_ratio, density);
  const VolumeMesh mesh = structured_grid(beam, {40, 4, 4}, ElementType::hex20);
  const auto fem = make_lagrange_discretization(mesh, *material, {clamp}, 5);
  const Discretization& discretization = *fem;

  const auto solver = make_linear_solver({});
  IntegratorOptions options;
  options.kind = IntegrationScheme::static_equilibrium;
  options.gravity = Eigen::Vector3d(0, 0, -g);
  // The default stopping rule (1e-5 ‖M g‖); one Newton step of a linear problem
  // ends at round-off, ~1e-8 of ‖M g‖ here, so a tighter rule would be unreachable.
  TimeIntegrator integrator(discretization, *solver, options);
  State state{Eigen::VectorXd::Zero(discretization.dof_count()), Eigen::VectorXd::Zero(discretization.dof_count())};
  integrator.apply_constraints(state);
  integrator.step(state);

  double sum = 0;
  int count = 0;
  for (Eigen::Index node = 0; node < mesh.nodes.rows(); ++node)
    if (std::abs(mesh.nodes(node, 0) - length) < 1e-12) {
      sum += state.displacement[3 * node + 2];
      ++count;
    }
  ASSERT_GT(count, 0);
  const double tip = -sum / count;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "[ beam     ] Hex20 [40,4,4], %d DOFs: tip deflection %.5e m, Timoshenko %.5e m "
      "(bending %.5e + shear %.5e), relative difference %+.3f%%, %.1f s\n",
      discretization.dof_count(), tip, timoshenko, bending, shear, 100 * (tip - timoshenko) / timoshenko, seconds);
  EXPECT_NEAR(tip, timoshenko, 0.02 * timoshenko);
}

}  // namespace
}  // namespace altfem
