#include "shared/solve/time_integrator.hpp"

#include <cstdio>

#include <algorithm>
#include <cmath>
#include <span>
#include <stdexcept>
#include <string>

#include "shared/common/error.hpp"
#include "shared/solve/lbfgs.hpp"
#include "shared/solve/process_ranks.hpp"

namespace altfem {

namespace {

// solver.nonlinear = lbfgs replaces Newton in the schemes that minimise a potential.
bool minimised_by_lbfgs(const IntegratorOptions& options) {
  return options.nonlinear == Minimizer::lbfgs && options.kind != IntegrationScheme::symplectic_euler &&
         options.kind != IntegrationScheme::semi_implicit;
}

// Static equilibrium: minimise Ψ(u) − f·u.
class StaticPotential final : public Objective {
public:
  StaticPotential(const Discretization& discretization, const Eigen::VectorXd& force)
      : discretization_(discretization), force_(force) {}
  double value(const Eigen::VectorXd& u) const override { return discretization_.energy(u) - force_.dot(u); }
  void gradient(const Eigen::VectorXd& u, Eigen::VectorXd& gradient) const override {
    discretization_.gradient(u, gradient);
    gradient -= force_;
  }
  void hessian(const Eigen::VectorXd& u, Eigen::SparseMatrix<double>& hessian, bool project_spd) const override {
    discretization_.hessian(u, hessian, project_spd);
  }
  bool hessian_is_constant() const override { return discretization_.hessian_is_constant(); }
  bool gradient_has_potential() const override { return discretization_.forces_have_potential(); }

private:
  const Discretization& discretization_;
  const Eigen::VectorXd& force_;
};

// Backward Euler as minimisation of the incremental potential (e.g. Gast et al. 2015;
// Longva et al. 2020 §6):
//   E(u) = 1/(2h²) (u − ũ)ᵀ M (u − ũ) + 1/(2h) (u − uₙ)ᵀ D (u − uₙ) + Ψ(u) − f·u,
// ũ = uₙ + h vₙ. Its gradient is M v̇ + D v + ∇Ψ − f, so the stopping rule of
// Longva et al. is a bound on this gradient. All matrices share one pattern, so the
// Hessian M/h² + D/h + K is a sum of value arrays.
class IncrementalPotential final : public Objective {
public:
  IncrementalPotential(const Discretization& discretization, double h, const Eigen::VectorXd& inertial_target,
                       const Eigen::VectorXd& previous, const Eigen::SparseMatrix<double>* damping,
                       const Eigen::VectorXd& force)
      : discretization_(discretization),
        h_(h),
        target_(inertial_target),
        previous_(previous),
        damping_(damping),
        force_(force) {}

  double value(const Eigen::VectorXd& u) const override {
    const double elastic = discretization_.energy(u);
    if (!std::isfinite(elastic)) return elastic;
    const Eigen::VectorXd inertial = u - target_;
    double value = 0.5 / (h_ * h_) * inertial.dot(discretization_.mass_times(inertial)) + elastic - force_.dot(u);
    if (damping_) {
      const Eigen::VectorXd moved = u - previous_;
      value += 0.5 / h_ * damping_share_sum(moved.dot(*damping_ * moved));
    }
    return value;
  }
  void gradient(const Eigen::VectorXd& u, Eigen::VectorXd& gradient) const override {
    discretization_.gradient(u, gradient);
    gradient.noalias() += discretization_.mass_times((u - target_) / (h_ * h_));
    if (damping_) {
      Eigen::VectorXd force = *damping_ * ((u - previous_) / h_);
      if (damping_is_share()) ranks::sum(std::span<double>(force.data(), static_cast<size_t>(force.size())));
      gradient += force;
    }
    gradient -= force_;
  }
  void hessian(const Eigen::VectorXd& u, Eigen::SparseMatrix<double>& hessian, bool project_spd) const override {
    discretization_.hessian(u, hessian, project_spd);
    discretization_.add_mass(1 / (h_ * h_), hessian);
    if (damping_)
      Eigen::Map<Eigen::VectorXd>(hessian.valuePtr(), hessian.nonZeros()) +=
          Eigen::Map<const Eigen::VectorXd>(damping_->valuePtr(), hessian.nonZeros()) / h_;
  }
  bool hessian_is_constant() const override { return discretization_.hessian_is_constant(); }
  bool gradient_has_potential() const override { return discretization_.forces_have_potential(); }

private:
  // D is built like the Hessian: each rank's share of it when the solver sums the shares.
  bool damping_is_share() const { return !discretization_.matrix_share_owners().empty(); }
  double damping_share_sum(double value) const { return damping_is_share() ? ranks::sum(value) : value; }

  const Discretization& discretization_;
  double h_;
  const Eigen::VectorXd& target_;
  const Eigen::VectorXd& previous_;
  const Eigen::SparseMatrix<double>* damping_;
  const Eigen::VectorXd& force_;
};

}  // namespace

std::string_view integration_scheme_name(IntegrationScheme kind) {
  switch (kind) {
    case IntegrationScheme::static_equilibrium: return "static";
    case IntegrationScheme::backward_euler: return "backward_euler";
    case IntegrationScheme::semi_implicit: return "semi_implicit";
    case IntegrationScheme::symplectic_euler: return "symplectic_euler";
  }
  return "unknown";
}

TimeIntegrator::TimeIntegrator(const Discretization& discretization, LinearSolver& linear_solver,
                               IntegratorOptions options)
    : linear_solver_(&linear_solver), options_(options) {
  rebind(discretization);
}

void TimeIntegrator::rebind(const Discretization& discretization, LinearSolver* linear_solver) {
  discretization_ = &discretization;
  if (linear_solver) linear_solver_ = linear_solver;
  elimination_ =
      std::make_unique<DirichletElimination>(discretization.hessian_pattern(), discretization.constrained_dofs());
  newton_ = std::make_unique<NewtonSolver>(*linear_solver_, discretization.hessian_pattern(), *elimination_,
                                           !discretization.matrix_share_owners().empty());
  gravity_force_ = discretization.body_force(options_.gravity);
  // The representative load: gravity's, else that of 1 m/s² along each axis.
  const Eigen::VectorXd representative =
      options_.gravity.norm() > 0 ? gravity_force_ : discretization.body_force(Eigen::Vector3d::Ones());
  absolute_tolerance_ = options_.tolerance * elimination_->free_norm(representative);
  if (!(absolute_tolerance_ > 0)) throw InputError("solver: the Newton tolerance is zero (no free DOF carries mass)");
}

void TimeIntegrator::apply_constraints(State& state) const {
  elimination_->set_constrained(state.displacement, discretization_->prescribed_displacement(state.time));
}

double TimeIntegrator::kinetic_energy(const State& state) const {
  if (options_.kind == IntegrationScheme::static_equilibrium) return 0;
  return options_.kind == IntegrationScheme::symplectic_euler
             ? discretization_->explicit_mass().kinetic_energy(state.velocity)
             : 0.5 * state.velocity.dot(discretization_->mass_times(state.velocity));
}

double TimeIntegrator::total_energy(const State& state) const {
  return kinetic_energy(state) + discretization_->energy(state.displacement) - gravity_force_.dot(state.displacement);
}

StepReport TimeIntegrator::step(State& state) {
  const long long linear_before = linear_solver_->statistics().iterations;
  failed_step_ = StepReport{};
  // A constant Hessian (a linear material) makes Newton's convergence independent of the
  // increment: retrying in smaller ones cannot help (a thin plate whose residual stalls
  // at round-off spent 57 s doing so).
  const bool retried =
      !minimised_by_lbfgs(options_) && options_.cutbacks > 0 && !discretization_->hessian_is_constant() &&
      (options_.kind == IntegrationScheme::static_equilibrium || options_.kind == IntegrationScheme::backward_euler);
  const State start = retried ? state : State{};
  std::string failure;
  int iterations = 0;
  try {
    StepReport report = attempt_step(state);
    if (options_.kind == IntegrationScheme::static_equilibrium) converged_load_factor_ = state.load_factor;
    return report;
  } catch (const NumericalError& error) {
    if (failed_step_.lbfgs_evaluations == 0) failed_step_.newton_iterations = newton_->iterations_of_last_call();
    failed_step_.linear_iterations = linear_solver_->statistics().iterations - linear_before;
    if (!retried) throw;
    failure = error.what();
    iterations = failed_step_.newton_iterations;
  }
  state = start;
  try {
    StepReport report = step_in_increments(state, start, failure, iterations);
    report.linear_iterations = linear_solver_->statistics().iterations - linear_before;
    if (options_.kind == IntegrationScheme::static_equilibrium) converged_load_factor_ = state.load_factor;
    return report;
  } catch (const NumericalError&) {
    failed_step_.newton_iterations = iterations;
    failed_step_.linear_iterations = linear_solver_->statistics().iterations - linear_before;
    throw;
  }
}

StepReport TimeIntegrator::attempt_step(State& state) {
  if (minimised_by_lbfgs(options_)) return step_lbfgs(state);
  switch (options_.kind) {
    case IntegrationScheme::symplectic_euler: return step_symplectic(state);
    case IntegrationScheme::semi_implicit: return step_implicit(state, true);
    default: return step_implicit(state, false);
  }
}

StepReport TimeIntegrator::step_in_increments(State& state, const State& start, const std::string& failure,
                                              int& iterations) {
  // Load stepping and time-step cutbacks as nonlinear finite-element codes do them
  // (e.g. Abaqus's automatic increments): the step is split into increments, halved
  // when one fails, doubled after one that converged in at most a quarter of the
  // iteration limit. An increment of a static step moves λ from the last converged
  // load factor towards the step's; one of backward Euler is a step of h · fraction.
  const bool is_static = options_.kind == IntegrationScheme::static_equilibrium;
  const double time_step = options_.time_step;
  const double smallest_allowed = std::ldexp(1.0, -options_.cutbacks);
  const double from_load = converged_load_factor_, to_load = start.load_factor;
  struct RestoreTimeStep {
    double& value;
    double saved;
    ~RestoreTimeStep() { value = saved; }
  } restore{options_.time_step, time_step};
  StepReport report;
  report.cutbacks = 1;  // the whole step failed
  double done = 0, increment = 0.5;
  while (done < 1) {
    increment = std::min(increment, 1 - done);
    const State before = state;
    const bool last = done + increment >= 1;
    if (is_static) state.load_factor = last ? to_load : from_load + (to_load - from_load) * (done + increment);
    else options_.time_step = last ? time_step * (1 - done) : time_step * increment;
    try {
      const StepReport part = step_implicit(state, false);
      state.step = start.step;  // increments are not steps: failures name the step they belong to
      iterations += part.newton_iterations;
      report.residual = part.residual;
      report.round_off_floor = std::max(report.round_off_floor, part.round_off_floor);
      report.smallest_increment = std::min(report.smallest_increment, increment);
      done = last ? 1 : done + increment;
      if (part.newton_iterations <= options_.max_iterations / 4) increment *= 2;
    } catch (const NumericalError& error) {
      iterations += newton_->iterations_of_last_call();
      state = before;
      ++report.cutbacks;
      increment /= 2;
      if (increment < smallest_allowed) {
        char where[160];
        std::snprintf(where, sizeof(where), "%s %.6g", is_static ? "load factor" : "time",
                      is_static ? from_load + (to_load - from_load) * done : start.time + time_step * done);
        throw NumericalError("step " + std::to_string(start.step + 1) + ": not converged in increments down to 2^-" +
                             std::to_string(options_.cutbacks) + " of the step (solver.cutbacks), reached " + where +
                             "; first failure: " + failure + "; last: " + error.what());
      }
    }
  }
  state.step = start.step + 1;
  if (is_static) state.load_factor = to_load;
  else state.time = start.time + time_step;
  report.newton_iterations = iterations;
  return report;
}

StepReport TimeIntegrator::step_implicit(State& state, bool single_step) {
  const long long linear_before = linear_solver_->statistics().iterations;
  NewtonOptions newton{absolute_tolerance_, options_.max_iterations, options_.line_search, options_.project_spd};
  NewtonReport report;
  if (options_.kind == IntegrationScheme::static_equilibrium) {
    // A load step: the fraction λ of the loads and of the prescribed displacements.
    discretization_->set_time(state.time);
    const double factor = state.load_factor;
    const Eigen::VectorXd force = factor * (gravity_force_ + discretization_->external_force(state.time));
    StaticPotential potential(*discretization_, force);
    report = newton_->minimize(potential, state.displacement,
                               factor * discretization_->prescribed_displacement(state.time), newton, state.step + 1);
    ++state.step;
  } else {
    const double h = options_.time_step;
    const double next_time = state.time + h;
    const Eigen::VectorXd previous = state.displacement;
    const Eigen::VectorXd target = previous + h * state.velocity;
    discretization_->set_time(next_time);
    const Eigen::VectorXd force = gravity_force_ + discretization_->external_force(next_time);
    Eigen::SparseMatrix<double> damping;
    const bool damped = options_.rayleigh_mass > 0 || options_.rayleigh_stiffness > 0;
    if (damped) {
      damping = discretization_->hessian_pattern();
      if (options_.rayleigh_stiffness > 0) discretization_->hessian(previous, damping, true);
      Eigen::Map<Eigen::VectorXd>(damping.valuePtr(), damping.nonZeros()) *= options_.rayleigh_stiffness;
      discretization_->add_mass(options_.rayleigh_mass, damping);
    }
    IncrementalPotential potential(*discretization_, h, target, previous, damped ? &damping : nullptr, force);
    const Eigen::VectorXd prescribed = discretization_->prescribed_displacement(next_time);
    report = single_step ? newton_->single_step(potential, state.displacement, prescribed, newton, state.step + 1)
                         : newton_->minimize(potential, state.displacement, prescribed, newton, state.step + 1);
    state.velocity = (state.displacement - previous) / h;
    state.time = next_time;
    ++state.step;
  }
  StepReport step_report{report.iterations, 0, linear_solver_->statistics().iterations - linear_before,
                         report.residual};
  step_report.round_off_floor = report.round_off_floor;
  return step_report;
}

StepReport TimeIntegrator::step_symplectic(State& state) {
  // Symplectic (semi-implicit) Euler with the method's explicit mass M_e (lumped for
  // Lagrange bases) and its matching body load f:
  //   v⁺ = v + h M_e⁻¹ (f − ∇Ψ(u) − αM_e v),  u⁺ = u + h v⁺;
  // constrained DOFs follow their prescribed motion.
  const double h = options_.time_step;
  Eigen::VectorXd internal;
  discretization_->set_time(state.time);
  discretization_->gradient(state.displacement, internal);
  const ExplicitMass& mass = discretization_->explicit_mass();
  Eigen::VectorXd force =
      discretization_->explicit_body_force(options_.gravity) + discretization_->external_force(state.time) - internal;
  if (options_.rayleigh_mass > 0) force -= options_.rayleigh_mass * mass.multiply(state.velocity);
  const Eigen::VectorXd previous = state.displacement;
  state.velocity += h * mass.solve(force);
  state.displacement += h * state.velocity;
  state.time += h;
  ++state.step;
  apply_constraints(state);
  for (int dof : discretization_->constrained_dofs())
    state.velocity[dof] = (state.displacement[dof] - previous[dof]) / h;
  if (!state.displacement.allFinite())
    throw NumericalError("step " + std::to_string(state.step) +
                         ": symplectic Euler diverged (non-finite displacement; the time step may exceed the "
                         "stability limit)");
  return StepReport{};
}

StepReport TimeIntegrator::step_lbfgs(State& state) {
  // The same potentials as Newton, minimised over the free DOFs by L-BFGS with the
  // constrained DOFs set to their prescribed values first.
  if (!discretization_->forces_have_potential())
    throw InputError(
        "solver: 'lbfgs' minimises an energy, and this discretization is a force model (dg warping): "
        "use the 'newton' nonlinear solver");
  const bool is_static = options_.kind == IntegrationScheme::static_equilibrium;
  const double h = options_.time_step;
  const double time = is_static ? state.time : state.time + h;
  const Eigen::VectorXd previous = state.displacement;
  const Eigen::VectorXd target = previous + h * state.velocity;
  discretization_->set_time(time);
  const double factor = is_static ? state.load_factor : 1.0;  // a static load step's λ
  const Eigen::VectorXd force = factor * (gravity_force_ + discretization_->external_force(time));
  StaticPotential static_potential(*discretization_, force);
  IncrementalPotential incremental(*discretization_, h, target, previous, nullptr, force);
  const Objective& objective = is_static ? static_cast<const Objective&>(static_potential) : incremental;

  Eigen::VectorXd u = state.displacement;
  elimination_->set_constrained(u, factor * discretization_->prescribed_displacement(time));
  std::vector<int> free;
  for (int dof = 0; dof < discretization_->dof_count(); ++dof)
    if (!elimination_->is_constrained(dof)) free.push_back(dof);
  Eigen::VectorXd x(static_cast<Eigen::Index>(free.size()));
  for (size_t i = 0; i < free.size(); ++i) x[static_cast<Eigen::Index>(i)] = u[free[i]];
  Eigen::VectorXd full_gradient;
  auto evaluate = [&](const Eigen::VectorXd& free_values, Eigen::VectorXd& free_gradient) {
    for (size_t i = 0; i < free.size(); ++i) u[free[i]] = free_values[static_cast<Eigen::Index>(i)];
    const double value = objective.value(u);
    free_gradient.resize(free_values.size());
    if (!std::isfinite(value)) {
      free_gradient.setZero();
      return value;
    }
    objective.gradient(u, full_gradient);
    for (size_t i = 0; i < free.size(); ++i) free_gradient[static_cast<Eigen::Index>(i)] = full_gradient[free[i]];
    return value;
  };
  LbfgsOptions lbfgs;
  lbfgs.gradient_tolerance = absolute_tolerance_;
  // Jacobi scaling from the Hessian at the start (lbfgs.hpp: without it Luksan's line
  // search stalls on the twisting beam, issue #22).
  Eigen::SparseMatrix<double> hessian = discretization_->hessian_pattern();
  objective.hessian(u, hessian, true);
  const Eigen::VectorXd diagonal = hessian.diagonal();
  lbfgs.scale.resize(x.size());
  for (size_t i = 0; i < free.size(); ++i) {
    const double d = std::abs(diagonal[free[i]]);
    lbfgs.scale[static_cast<Eigen::Index>(i)] = d > 0 ? 1.0 / std::sqrt(d) : 1.0;
  }
  lbfgs.max_evaluations = 100 * options_.max_iterations;
  const LbfgsResult result = minimize_lbfgs(evaluate, x, lbfgs);
  failed_step_.lbfgs_evaluations = result.evaluations;
  if (result.status != LbfgsStatus::converged)
    throw NumericalError("step " + std::to_string(state.step + 1) + ", L-BFGS evaluation " +
                         std::to_string(result.evaluations) + ": not converged (" + result.detail +
                         "), gradient norm " + std::to_string(result.gradient_norm) + " > tolerance " +
                         std::to_string(absolute_tolerance_));
  for (size_t i = 0; i < free.size(); ++i) u[free[i]] = x[static_cast<Eigen::Index>(i)];
  state.displacement = u;
  if (!is_static) {
    state.velocity = (state.displacement - previous) / h;
    state.time = time;
  }
  ++state.step;
  return StepReport{0, result.evaluations, 0, result.gradient_norm};
}

}  // namespace altfem
