// Time integrators over a Lagrange TabulatedDiscretization: exact free fall for every scheme, and a
// linear material analysed and factorised once for a whole run.
#include <gtest/gtest.h>

#include "shared/fem/lagrange_discretization.hpp"
#include "shared/solve/time_integrator.hpp"
#include "tests/unit/fem/test_meshes.hpp"

namespace altfem {
namespace {

const Eigen::Vector3d gravity(0.0, 0.0, -9.81);

DirichletCondition clamp_x_min() {
  DirichletCondition condition;
  condition.region.kind = RegionKind::box;
  condition.region.box = Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(0, 2, 2));
  condition.motion.kind = MotionKind::fixed;
  condition.pointer = "/boundary_conditions/0";
  return condition;
}

class FreeFall : public ::testing::TestWithParam<IntegrationScheme> {};

// A free body under gravity translates rigidly, so ∇Ψ = 0 and every scheme reduces to
// v_{n+1} = v_n + h g, u_{n+1} = u_n + h v_{n+1}: u_n = g h² n(n+1)/2, v_n = n h g
// (backward Euler's single Newton step is exact because K annihilates translations).
TEST_P(FreeFall, MatchesTheDiscreteRecurrenceExactly) {
  const auto material = make_material(MaterialModel::stable_neo_hookean, 1e5, 0.3, 1000);
  const auto fem =
      make_lagrange_discretization(structured_grid(test::unit_cube(), {2, 2, 2}, ElementType::tet10), *material, {}, 4);
  const Discretization& discretization = *fem;
  const auto solver = make_linear_solver({});
  IntegratorOptions options;
  options.kind = GetParam();
  options.time_step = 0.01;
  options.gravity = gravity;
  options.tolerance = 1e-9;
  TimeIntegrator integrator(discretization, *solver, options);
  State state{Eigen::VectorXd::Zero(discretization.dof_count()), Eigen::VectorXd::Zero(discretization.dof_count())};
  const int steps = 10;
  for (int n = 0; n < steps; ++n) integrator.step(state);
  EXPECT_EQ(state.step, steps);
  EXPECT_NEAR(state.time, steps * options.time_step, 1e-15);
  const double h = options.time_step;
  const Eigen::Vector3d u = gravity * h * h * steps * (steps + 1) / 2, v = gravity * h * steps;
  for (Eigen::Index node = 0; node < discretization.dof_count() / 3; ++node) {
    EXPECT_LT((state.displacement.segment<3>(3 * node) - u).norm(), 1e-10 * u.norm()) << "node " << node;
    EXPECT_LT((state.velocity.segment<3>(3 * node) - v).norm(), 1e-10 * v.norm()) << "node " << node;
  }
}

INSTANTIATE_TEST_SUITE_P(TimeIntegrator, FreeFall,
                         ::testing::Values(IntegrationScheme::backward_euler, IntegrationScheme::semi_implicit,
                                           IntegrationScheme::symplectic_euler),
                         [](const auto& info) { return std::string(integration_scheme_name(info.param)); });

TEST(TimeIntegrator, LinearMaterialAnalysesAndFactorisesOnce) {
  const auto material = make_material(MaterialModel::linear, 1e6, 0.3, 1000);
  const auto fem = make_lagrange_discretization(structured_grid(test::unit_cube(), {3, 2, 2}, ElementType::hex8),
                                                *material, {clamp_x_min()}, 3);
  const Discretization& discretization = *fem;
  EXPECT_TRUE(discretization.hessian_is_constant());
  const auto solver = make_linear_solver({});
  IntegratorOptions options;
  options.kind = IntegrationScheme::backward_euler;
  options.time_step = 0.01;
  options.gravity = gravity;
  TimeIntegrator integrator(discretization, *solver, options);
  State state{Eigen::VectorXd::Zero(discretization.dof_count()), Eigen::VectorXd::Zero(discretization.dof_count())};
  int newton_iterations = 0;
  for (int n = 0; n < 6; ++n) newton_iterations += integrator.step(state).newton_iterations;
  EXPECT_GE(newton_iterations, 6);
  EXPECT_LT(state.displacement.minCoeff(), 0.0);  // it sags
  const LinearSolverStatistics& statistics = solver->statistics();
  EXPECT_EQ(statistics.analyses, 1);
  EXPECT_EQ(statistics.factorisations, 1);
  EXPECT_EQ(statistics.solves, newton_iterations);
  for (int dof : discretization.constrained_dofs()) EXPECT_EQ(state.displacement[dof], 0.0);
}

}  // namespace
}  // namespace altfem
