// Issue #22: L-BFGS on the shipped twisting beam (here at a coarser mesh and 10 of its
// 50 steps, to stay within seconds) reaches Newton's equilibrium under the same
// stopping rule (Longva et al. 2020 §6), step after step.
#include <gtest/gtest.h>

#include <cstdio>

#include "shared/fem/method/fem_method.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/solve/time_integrator.hpp"

namespace altfem {
namespace {

Eigen::VectorXd final_displacement(Minimizer minimizer, long long& iterations) {
  const Scene scene = load_scene(ALTFEM_SOURCE_DIR "/tests/verify/fem/scenes/twisting_beam_coarse.json");
  const SceneGeometry geometry = load_scene_geometry(scene);
  const auto method = make_fem_method(scene, geometry);
  const Discretization& discretization = method->discretization();
  const auto solver = make_linear_solver({});
  IntegratorOptions options;
  options.kind = IntegrationScheme::backward_euler;
  options.nonlinear = minimizer;
  options.time_step = scene.time.dt;
  options.tolerance = scene.solver.tolerance;
  TimeIntegrator integrator(discretization, *solver, options);
  State state{Eigen::VectorXd::Zero(discretization.dof_count()), Eigen::VectorXd::Zero(discretization.dof_count())};
  integrator.apply_constraints(state);
  iterations = 0;
  for (int step = 0; step < scene.time.steps; ++step) {
    const StepReport report = integrator.step(state);
    iterations += report.newton_iterations + report.lbfgs_evaluations;
  }
  return state.displacement;
}

TEST(LbfgsTwistingBeam, ReachesNewtonsEquilibrium) {
  long long newton_iterations = 0, lbfgs_evaluations = 0;
  const Eigen::VectorXd newton = final_displacement(Minimizer::newton, newton_iterations);
  const Eigen::VectorXd lbfgs = final_displacement(Minimizer::lbfgs, lbfgs_evaluations);
  ASSERT_EQ(newton.size(), lbfgs.size());
  const double difference = (newton - lbfgs).cwiseAbs().maxCoeff() / newton.cwiseAbs().maxCoeff();
  std::printf(
      "  10 steps: Newton %lld iterations, L-BFGS %lld evaluations; max |u_lbfgs - u_newton| / max |u| = %.2e\n",
      newton_iterations, lbfgs_evaluations, difference);
  EXPECT_LT(difference, 1e-5);
}

}  // namespace
}  // namespace altfem
