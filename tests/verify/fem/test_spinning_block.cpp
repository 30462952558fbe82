// A free block spinning about z (no constraints, no gravity): symplectic Euler keeps
// the total energy, backward Euler dissipates it monotonically; and the internal
// force of a rigid rotation vanishes for every nonlinear (rotation-invariant) model.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <chrono>

#include "shared/common/eigen_decompositions.hpp"
#include "shared/fem/lagrange_discretization.hpp"
#include "shared/fem/tabulate_lagrange.hpp"
#include "shared/solve/time_integrator.hpp"
#include "tests/unit/fem/test_meshes.hpp"

namespace altfem {
namespace {

const Eigen::AlignedBox3d block(Eigen::Vector3d(-0.5, -0.5, -0.25), Eigen::Vector3d(0.5, 0.5, 0.25));
constexpr double angular_velocity = 1.0;  // rad/s about z

struct SpinningBlock {
  std::unique_ptr<Material> material = make_material(MaterialModel::stable_neo_hookean, 1e5, 0.3, 1000);
  VolumeMesh mesh = structured_grid(block, {3, 3, 2}, ElementType::hex8);
  std::unique_ptr<TabulatedDiscretization> fem = make_lagrange_discretization(mesh, *material, {}, 3);
  const TabulatedDiscretization& discretization = *fem;

  State initial_state() const {
    const int dofs = discretization.dof_count();
    State state{Eigen::VectorXd::Zero(dofs), Eigen::VectorXd::Zero(dofs)};
    InitialConditions initial;
    initial.angular_velocity = Eigen::Vector3d(0, 0, angular_velocity);
    const Eigen::Vector3d centre = block.center();  // uniform density
    for (Eigen::Index node = 0; node < dofs / 3; ++node)
      state.velocity.segment<3>(3 * node) = initial.velocity_at(mesh.nodes.row(node).transpose(), centre);
    return state;
  }
  /// The explicit stability limit 2/ω_max, ω_max² the largest eigenvalue of
  /// M_L^{-1/2} K M_L^{-1/2} at rest.
  double stability_limit() const {
    Eigen::SparseMatrix<double> stiffness = discretization.hessian_pattern();
    discretization.hessian(Eigen::VectorXd::Zero(discretization.dof_count()), stiffness, false);
    const auto& lumped = dynamic_cast<const DiagonalMass&>(discretization.explicit_mass());
    const Eigen::VectorXd scale = lumped.diagonal().cwiseSqrt().cwiseInverse();
    const Eigen::MatrixXd scaled = scale.asDiagonal() * Eigen::MatrixXd(stiffness) * scale.asDiagonal();
    const double largest =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(scaled, Eigen::EigenvaluesOnly).eigenvalues().maxCoeff();
    return 2.0 / std::sqrt(largest);
  }
};

double elapsed(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

TEST(SpinningBlock, SymplecticEulerConservesEnergyWithinOnePercent) {
  const auto start = std::chrono::steady_clock::now();
  const SpinningBlock spinning;
  const double limit = spinning.stability_limit();
  const auto solver = make_linear_solver({});
  IntegratorOptions options;
  options.kind = IntegrationScheme::symplectic_euler;
  options.time_step = 0.5 * limit;
  TimeIntegrator integrator(spinning.discretization, *solver, options);
  State state = spinning.initial_state();
  const double initial = integrator.total_energy(state);
  ASSERT_GT(initial, 0.0);
  double worst = 0;
  for (int n = 0; n < 1000; ++n) {
    integrator.step(state);
    worst = std::max(worst, std::abs(integrator.total_energy(state) - initial) / initial);
  }
  const double angle = 1000 * options.time_step * angular_velocity;
  std::printf(
      "[ spin     ] symplectic Euler: dt %.3e s (limit %.3e s), 1000 steps (%.2f rad), worst relative "
      "energy drift %.2e, %.2f s\n",
      options.time_step, limit, angle, worst, elapsed(start));
  EXPECT_LT(worst, 0.01);
  // It did spin: a rotation by θ moves the outermost corners (radius √0.5) by 2 r sin(θ/2).
  double largest = 0;
  for (Eigen::Index node = 0; node < state.displacement.size() / 3; ++node)
    largest = std::max(largest, state.displacement.segment<3>(3 * node).norm());
  EXPECT_NEAR(largest, 2 * std::sqrt(0.5) * std::abs(std::sin(angle / 2)), 0.05);
}

TEST(SpinningBlock, BackwardEulerDissipatesMonotonically) {
  const auto start = std::chrono::steady_clock::now();
  const SpinningBlock spinning;
  const auto solver = make_linear_solver({});
  IntegratorOptions options;
  options.kind = IntegrationScheme::backward_euler;
  options.time_step = 0.01;  // the default stopping rule (see test_newton.cpp for why not tighter)
  TimeIntegrator integrator(spinning.discretization, *solver, options);
  State state = spinning.initial_state();
  const double initial = integrator.total_energy(state);
  double previous = initial;
  int newton = 0;
  for (int n = 0; n < 100; ++n) {
    newton += integrator.step(state).newton_iterations;
    const double energy = integrator.total_energy(state);
    EXPECT_LE(energy, previous + 1e-12 * initial) << "step " << n + 1;
    previous = energy;
  }
  std::printf(
      "[ spin     ] backward Euler: dt 0.01 s, 100 steps, %d Newton iterations, energy %.6e -> %.6e "
      "(%.3f%% dissipated), %.2f s\n",
      newton, initial, previous, 100 * (initial - previous) / initial, elapsed(start));
  EXPECT_LT(previous, initial * (1 - 1e-4));
}

TEST(RigidRotation, NoInternalForceForEveryNonlinearModel) {
  const VolumeMesh mesh = test::distorted_grid(test::unit_cube(), {3, 3, 3}, ElementType::tet10, 0.15, 31);
  const TabulatedElements elements = tabulate_lagrange(mesh, 4);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(1.0, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::VectorXd u = test::nodal_values(
      mesh, [&](const Eigen::Vector3d& x) -> Eigen::Vector3d { return (R - Eigen::Matrix3d::Identity()) * x; });
  constexpr double youngs_modulus = 1e6, h = 1.0 / 3;
  const double force_scale = youngs_modulus * h * h;  // stress E on a face of size h²
  for (MaterialModel model : all_material_models) {
    const auto material = make_material(model, youngs_modulus, 0.3, 1000);
    const ElasticAssembler assembler(elements, {material.get()});
    Eigen::VectorXd gradient;
    assembler.gradient(u, gradient);
    const double relative = gradient.lpNorm<Eigen::Infinity>() / force_scale;
    std::printf("[ rotation ] %s: max |internal force| / (E h^2) = %.2e\n",
                std::string(material_model_name(model)).c_str(), relative);
    if (model == MaterialModel::linear)
      EXPECT_GT(relative, 1e-2) << "linear elasticity is not rotation invariant: the check must see it";
    else EXPECT_LT(relative, 1e-12) << material_model_name(model);
  }
}

}  // namespace
}  // namespace altfem
