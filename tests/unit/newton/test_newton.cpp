// NewtonSolver on a one-element-per-axis nonlinear problem: quadratic convergence,
// and one symbolic analysis with one factorisation per iteration.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "shared/common/error.hpp"

#include "shared/assembly/elastic_assembler.hpp"
#include "shared/fem/tabulate_lagrange.hpp"
#include "shared/solve/newton.hpp"
#include "tests/unit/fem/test_meshes.hpp"
#include "tests/unit/newton/loaded_potential.hpp"

namespace altfem {
namespace {

using test::LoadedPotential;

std::string format_residual(double value) {
  char text[32];
  std::snprintf(text, sizeof text, " %.3e", value);
  return text;
}

struct Block {
  VolumeMesh mesh = structured_grid(test::unit_cube(), {1, 1, 1}, ElementType::hex8);
  TabulatedElements elements = tabulate_lagrange(mesh, 3);
  std::unique_ptr<Material> material = make_material(MaterialModel::neo_hookean, 1e4, 0.3, 1000);
  ElasticAssembler assembler{elements, {material.get()}};
  std::vector<int> clamped;  // the x = 0 face
  Eigen::VectorXd force;     // on the x = 1 face: pull and shear, ~30% strain

  Block() {
    force = Eigen::VectorXd::Zero(assembler.dof_count());
    for (int node = 0; node < mesh.nodes.rows(); ++node) {
      if (mesh.nodes(node, 0) == 0.0)
        for (int k = 0; k < 3; ++k) clamped.push_back(3 * node + k);
      else force.segment<3>(3 * node) = Eigen::Vector3d(800.0, 0.0, 300.0);
    }
  }
};

TEST(Newton, ConvergesQuadraticallyWithOneAnalysisAndOneFactorisationPerIteration) {
  Block block;
  const DirichletElimination elimination(block.assembler.pattern(), block.clamped);
  LoadedPotential objective(block.assembler, block.force, elimination);
  const auto solver = make_linear_solver({});
  NewtonSolver newton(*solver, block.assembler.pattern(), elimination);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(block.assembler.dof_count());
  NewtonOptions options;
  options.tolerance = 1e-11 * block.force.norm();
  const Eigen::VectorXd prescribed = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(block.clamped.size()));
  const NewtonReport report = newton.minimize(objective, u, prescribed, options, 0);

  const std::vector<double>& r = objective.residuals;
  ASSERT_EQ(static_cast<int>(r.size()), report.iterations + 1);
  EXPECT_LE(report.residual, options.tolerance);
  EXPECT_GT(u.segment<3>(3 * 1).x(), 0.2);  // node 1 is at x = 1: a large, nonlinear stretch
  std::string history;
  for (double value : r) history += format_residual(value);
  std::printf("[ newton   ] free residuals:%s\n", history.c_str());
  // Convergence order log(r_{k+1}/r_k) / log(r_k/r_{k−1}) over the iterations in the
  // asymptotic regime (r_k ≤ 1e-2 r_0) and above round-off (r_{k+1} ≥ 1e-13 r_0).
  int measured = 0;
  for (size_t k = 1; k + 1 < r.size(); ++k) {
    if (r[k] > 1e-2 * r[0] || r[k + 1] < 1e-13 * r[0]) continue;
    const double order = std::log(r[k + 1] / r[k]) / std::log(r[k] / r[k - 1]);
    EXPECT_GT(order, 1.8) << "iteration " << k << ", residuals" << history;
    ++measured;
  }
  EXPECT_GE(measured, 1) << "residuals" << history;

  EXPECT_EQ(report.round_off_floor, 0) << "stopped by the tolerance, not at round-off";
  const LinearSolverStatistics& statistics = solver->statistics();
  EXPECT_EQ(statistics.analyses, 1);
  EXPECT_EQ(statistics.factorisations, report.iterations);
  EXPECT_EQ(statistics.solves, report.iterations);

  // A second solve with the same solver (a larger load): no new analysis.
  objective.residuals.clear();
  LoadedPotential heavier(block.assembler, 1.2 * block.force, elimination);
  const NewtonReport second = newton.minimize(heavier, u, prescribed, options, 1);
  EXPECT_GT(second.iterations, 0);
  EXPECT_EQ(solver->statistics().analyses, 1);
  EXPECT_EQ(solver->statistics().factorisations, report.iterations + second.iterations);
}

// A tolerance of 0 cannot be met: with a linear material Newton stops once the residual
// reaches the round-off floor 16 ε ‖(|H||u|)_free‖ of the forces it assembles (issue
// #35, the 1 mm plate), after its one solve; the floor lies 14 orders below the load.
// A nonlinear material has no such stop (its forces are not H u): it runs out of
// iterations.
TEST(Newton, AnUnreachableToleranceStopsAtTheRoundOffFloorOfALinearMaterial) {
  Block block;
  // Minimises the block's potential of `model` from rest with a tolerance of 0 and at
  // most `iterations` Newton iterations.
  const auto minimize_exactly = [&block](MaterialModel model, int iterations) {
    const auto material = make_material(model, 1e4, 0.3, 1000);
    const ElasticAssembler assembler(block.elements, {material.get()});
    const DirichletElimination elimination(assembler.pattern(), block.clamped);
    LoadedPotential objective(assembler, block.force, elimination);
    const auto solver = make_linear_solver({});
    NewtonSolver newton(*solver, assembler.pattern(), elimination);
    Eigen::VectorXd u = Eigen::VectorXd::Zero(assembler.dof_count());
    NewtonOptions options;
    options.tolerance = 0;
    options.max_iterations = iterations;
    const Eigen::VectorXd prescribed = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(block.clamped.size()));
    return newton.minimize(objective, u, prescribed, options, 0);
  };
  EXPECT_THROW(minimize_exactly(MaterialModel::neo_hookean, 20), NumericalError);
  const NewtonReport report = minimize_exactly(MaterialModel::linear, 50);
  EXPECT_GT(report.round_off_floor, 0);
  EXPECT_LE(report.residual, report.round_off_floor);
  EXPECT_LT(report.round_off_floor, 1e-12 * block.force.norm());
  EXPECT_LE(report.iterations, 2);
}

// Known bug (see the report to the lead): the Armijo test compares objective values
// whose round-off is set by the energy's terms (Stable Neo-Hookean's ψ is a sum of
// O(μ) terms minus its rest energy: ~1e-16 μ V), not by |objective|. Near the
// solution of a small-load problem the predicted decrease falls below that noise,
// the full Newton step is rejected and Newton stalls far above a tolerance that the
// gradient itself reaches easily (here: one step from converged).
TEST(Newton, ConvergesWhenTheDecreaseIsBelowTheEnergyRoundOff) {
  Block block;
  const auto material = make_material(MaterialModel::stable_neo_hookean, 1e4, 0.3, 1000);
  const ElasticAssembler assembler(block.elements, {material.get()});
  const DirichletElimination elimination(assembler.pattern(), block.clamped);
  const Eigen::VectorXd force = 1e-4 * block.force;  // ~1e-5 strain
  LoadedPotential objective(assembler, force, elimination);
  const auto solver = make_linear_solver({});
  NewtonSolver newton(*solver, assembler.pattern(), elimination);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(assembler.dof_count());
  NewtonOptions options;
  options.tolerance = 1e-9 * force.norm();
  options.max_iterations = 10;
  const Eigen::VectorXd prescribed = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(block.clamped.size()));
  std::string history;
  try {
    newton.minimize(objective, u, prescribed, options, 0);
  } catch (const NumericalError& error) {
    for (double value : objective.residuals) history += format_residual(value / force.norm());
    ADD_FAILURE() << error.what() << "; relative residuals" << history;
  }
}

TEST(Newton, PrescribedDisplacementIsReachedExactly) {
  Block block;
  // Clamp x = 0 and move the x = 1 face by (0.2, 0.05, −0.1): no force.
  std::vector<int> constrained;
  Eigen::VectorXd targets(24);
  int count = 0;
  for (int node = 0; node < block.mesh.nodes.rows(); ++node)
    for (int k = 0; k < 3; ++k) {
      constrained.push_back(3 * node + k);
      targets[count++] = block.mesh.nodes(node, 0) == 0.0 ? 0.0 : Eigen::Vector3d(0.2, 0.05, -0.1)[k];
    }
  // Every DOF constrained except those of node 6's z: a single free DOF.
  const int free_dof = 3 * 6 + 2;
  std::vector<int> kept;
  Eigen::VectorXd prescribed(23);
  for (int i = 0, j = 0; i < 24; ++i)
    if (constrained[i] != free_dof) {
      kept.push_back(constrained[i]);
      prescribed[j++] = targets[i];
    }
  const DirichletElimination elimination(block.assembler.pattern(), kept);
  LoadedPotential objective(block.assembler, Eigen::VectorXd::Zero(24), elimination);
  const auto solver = make_linear_solver({});
  NewtonSolver newton(*solver, block.assembler.pattern(), elimination);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(24);
  NewtonOptions options;
  options.tolerance = 1e-9;
  const NewtonReport report = newton.minimize(objective, u, prescribed, options, 0);
  EXPECT_LE(report.iterations, 10);
  EXPECT_LT((elimination.constrained_values(u) - prescribed).lpNorm<Eigen::Infinity>(), 1e-15);
  Eigen::VectorXd gradient;
  block.assembler.gradient(u, gradient);
  EXPECT_LE(std::abs(gradient[free_dof]), 1e-9);
}

}  // namespace
}  // namespace altfem
