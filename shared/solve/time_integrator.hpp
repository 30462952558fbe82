#pragma once
// Static equilibrium and the time integrators (docs/architecture.md), over any Discretization.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <string>
#include <string_view>

#include "shared/solve/dirichlet_elimination.hpp"
#include "shared/solve/discretization.hpp"
#include "shared/solve/linear_solver.hpp"
#include "shared/solve/newton.hpp"

namespace altfem {

enum class IntegrationScheme { static_equilibrium, backward_euler, semi_implicit, symplectic_euler };
enum class Minimizer { newton, lbfgs };

struct IntegratorOptions {
  IntegrationScheme kind = IntegrationScheme::static_equilibrium;
  Minimizer nonlinear = Minimizer::newton;
  double time_step = 1.0;  ///< h [s]; unused by static equilibrium
  /// Longva et al. 2020 §6: stop when ‖M v̇ − f‖ ≤ tolerance · ‖M a_rep‖ (free DOFs),
  /// with gravity as the representative acceleration a_rep (1 m/s² along each axis
  /// when the scene has no gravity). For statics the residual is ‖∇Ψ − f‖.
  double tolerance = 1e-5;
  int max_iterations = 50;
  bool line_search = true;
  bool project_spd = false;
  double rayleigh_mass = 0;       ///< α of D = αM + βK
  double rayleigh_stiffness = 0;  ///< β of D = αM + βK, K frozen at the start of each step
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
  /// Newton steps of static equilibrium and backward Euler that fail are retried in
  /// increments: halved on failure, doubled after an easy one, down to 2^-cutbacks of
  /// the step (0: no retry).
  int cutbacks = 10;
};

struct State {
  Eigen::VectorXd displacement, velocity;  ///< #dofs each
  double time = 0;
  int step = 0;
  /// Static equilibrium only: the fraction λ of the loads and prescribed displacements
  /// (at `time`) a load step applies (time.load_steps: λ = k / load_steps).
  double load_factor = 1.0;
};

struct StepReport {
  int newton_iterations = 0;
  int lbfgs_evaluations = 0;  ///< L-BFGS steps report objective evaluations here, not as Newton iterations
  long long linear_iterations = 0;
  double residual = 0;
  /// Failed attempts the step was retried after (IntegratorOptions::cutbacks), and the
  /// smallest increment that converged, as a fraction of the step (1 without retry).
  int cutbacks = 0;
  double smallest_increment = 1;
  /// When Newton stopped above the tolerance at the round-off floor of the assembled
  /// forces (NewtonReport::round_off_floor): the largest such floor of the step; else 0.
  double round_off_floor = 0;
};

std::string_view integration_scheme_name(IntegrationScheme kind);

class TimeIntegrator {
public:
  TimeIntegrator(const Discretization& discretization, LinearSolver& linear_solver, IntegratorOptions options);

  /// Continues with another discretization (an event changed the constrained DOFs or the
  /// method): rebuilds what was cached from the old one (the elimination, Newton's
  /// pattern, the gravity load and the tolerance). The state (time, step) is the
  /// caller's; the linear solver keeps its statistics and re-analyses only when the
  /// pattern changed.
  /// With `linear_solver`, solves with it from now on (a new discretization may bring
  /// its own preconditioner).
  void rebind(const Discretization& discretization, LinearSolver* linear_solver = nullptr);

  /// Prescribed displacements and velocities at the state's time.
  void apply_constraints(State& state) const;
  /// Advances the state by one time step (static equilibrium: solves once, at the
  /// state's time). Throws NumericalError naming the step.
  StepReport step(State& state);
  /// What the last step() spent before it threw: its Newton iterations or L-BFGS
  /// evaluations, and linear iterations (a failed run's counters include them).
  StepReport failed_step_report() const { return failed_step_; }
  /// Kinetic (½ vᵀ M v, the explicit mass for symplectic Euler) plus elastic energy, minus
  /// the potential of gravity.
  double total_energy(const State& state) const;
  /// ½ vᵀ M v with the mass the scheme uses (explicit for symplectic Euler, else consistent).
  double kinetic_energy(const State& state) const;
  /// The absolute Newton tolerance: tolerance · ‖M a_rep‖ over the free DOFs.
  double absolute_tolerance() const { return absolute_tolerance_; }

private:
  StepReport attempt_step(State& state);
  /// The step from `start` (restored in `state`) in increments after it failed whole
  /// with `failure`; `iterations` accumulates the Newton iterations of every attempt.
  StepReport step_in_increments(State& state, const State& start, const std::string& failure, int& iterations);
  StepReport step_implicit(State& state, bool single_step);
  StepReport step_symplectic(State& state);
  StepReport step_lbfgs(State& state);

  const Discretization* discretization_ = nullptr;
  LinearSolver* linear_solver_;
  IntegratorOptions options_;
  std::unique_ptr<DirichletElimination> elimination_;
  std::unique_ptr<NewtonSolver> newton_;
  Eigen::VectorXd gravity_force_;  // ∫ρ g φ
  StepReport failed_step_;
  double absolute_tolerance_ = 0;
  double converged_load_factor_ = 0;  // static equilibrium: λ of the last load step that converged
};

}  // namespace altfem
