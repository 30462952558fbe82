#include "shared/simulation/simulation.hpp"

#include <omp.h>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <future>
#include <limits>

#include "shared/common/error.hpp"
#include "shared/mesh/cut_surface.hpp"
#include "shared/simulation/body_force_load.hpp"
#include "shared/simulation/rigid_motion.hpp"
#include "shared/simulation/surface_traction.hpp"
#include "shared/solve/critical_time_step.hpp"
#include "shared/solve/process_ranks.hpp"

namespace altfem {

namespace {

// OpenMP one thread fewer (at least one) while it lives, on the thread that made it: a
// thread of our own holds a core meanwhile, which parallel loops would otherwise take from
// it (the pencil's dg cut: 4.3 ms with the rebuild's loops on both cores beside the
// surface's cut, 3.1 ms with one).
class CoreLentOut {
public:
  explicit CoreLentOut(bool lent) : threads_(omp_get_max_threads()) {
    if (lent) omp_set_num_threads(std::max(1, threads_ - 1));
  }
  ~CoreLentOut() { omp_set_num_threads(threads_); }
  CoreLentOut(const CoreLentOut&) = delete;
  CoreLentOut& operator=(const CoreLentOut&) = delete;

private:
  int threads_;
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A static problem with a load and nothing holding the body has no equilibrium: its
// rigid-body modes move without bound. Caught before solving, as bad input.
void check_static_supports(const Scene& scene, const Discretization& discretization) {
  if (!scene.time.is_static || !discretization.constrained_dofs().empty() || discretization.imposes_conditions_weakly())
    return;
  const bool loaded = scene.gravity.norm() > 0 || discretization.external_force(1.0).norm() > 0;
  if (loaded)
    throw InputError(input_message(scene.file.string(), "/boundary_conditions",
                                   "a static problem with a load needs Dirichlet conditions that hold the body "
                                   "(none selects any DOF): its rigid-body modes have no equilibrium; add a "
                                   "condition, or add a time block for a dynamic run"));
}

// The scene's loads that every method gets the same way, each a load vector at a time,
// added to the method's own external force: a new kind adds its line here.
std::vector<TimeDependentLoad> scene_loads(const Scene& scene, const SceneGeometry& geometry,
                                           const MethodInstance& method, const std::string& method_name) {
  std::vector<TimeDependentLoad> loads;
  if (auto tractions = surface_traction_load(scene, geometry.bounds, method)) loads.push_back(std::move(tractions));
  if (auto body_force = body_force_load(scene, method, method_name)) loads.push_back(std::move(body_force));
  return loads;
}

void add_statistics(LinearSolverStatistics& total, const LinearSolverStatistics& more) {
  total.analyses += more.analyses;
  total.factorisations += more.factorisations;
  total.solves += more.solves;
  total.iterations += more.iterations;
  total.analysis_seconds += more.analysis_seconds;
  total.factorisation_seconds += more.factorisation_seconds;
  total.solve_seconds += more.solve_seconds;
  total.factor_entries = more.factor_entries;
  total.factorisation_flops = more.factorisation_flops;
  if (more.fewest_blas_threads > 0)
    total.fewest_blas_threads = total.fewest_blas_threads == 0
                                    ? more.fewest_blas_threads
                                    : std::min(total.fewest_blas_threads, more.fewest_blas_threads);
  total.most_blas_threads = std::max(total.most_blas_threads, more.most_blas_threads);
}

}  // namespace

IntegratorOptions integrator_options(const Scene& scene) {
  IntegratorOptions options;
  if (scene.time.is_static) {
    options.kind = IntegrationScheme::static_equilibrium;
  } else {
    switch (scene.time.integrator) {
      case IntegratorKind::backward_euler: options.kind = IntegrationScheme::backward_euler; break;
      case IntegratorKind::symplectic_euler: options.kind = IntegrationScheme::symplectic_euler; break;
      case IntegratorKind::semi_implicit: options.kind = IntegrationScheme::semi_implicit; break;
    }
    options.time_step = scene.time.dt;
  }
  options.nonlinear = scene.solver.nonlinear == NonlinearSolverKind::lbfgs ? Minimizer::lbfgs : Minimizer::newton;
  options.tolerance = scene.solver.tolerance;
  options.max_iterations = scene.solver.max_iterations;
  options.line_search = scene.solver.line_search;
  options.cutbacks = scene.solver.cutbacks;
  options.project_spd = scene.solver.project_spd;
  options.rayleigh_mass = scene.time.rayleigh_mass;
  options.rayleigh_stiffness = scene.time.rayleigh_stiffness;
  options.gravity = scene.gravity;
  return options;
}

LinearSolverOptions linear_solver_options(const Scene& scene, const MethodInstance& method) {
  LinearSolverOptions options;
  options.kind = scene.solver.linear;
  options.preconditioner = scene.solver.preconditioner;
  options.custom_preconditioner = method.discretization().preconditioner_factory();
  options.tolerance = scene.solver.linear_tolerance;
  options.max_iterations = scene.solver.linear_max_iterations;
  if (options.kind == LinearSolverKind::petsc) {
    options.petsc_options = scene.solver.petsc_options;
    options.share_row_owners = method.discretization().matrix_share_owners();
    if (scene.solver.rigid_body_modes) options.near_null_space = rigid_body_modes(method);
    options.method_smoother = scene.solver.method_smoother;
    if (scene.solver.p_multigrid) options.coarse_space = method.discretization().coarse_space();
    // One set-up serves every solve where the Hessian is constant (a linear material) and
    // the run solves more than once: there a GAMG set-up without aggressive coarsening
    // pays for itself in fewer iterations at every solve, where a single solve's does not
    // (docs/performance.md, the PETSc section).
    const int solves = scene.time.is_static ? scene.time.load_steps : scene.time.steps;
    options.aggressive_coarsening = !(method.discretization().hessian_is_constant() && solves > 1);
  }
  return options;
}

Simulation::Simulation(const Scene& scene, const SceneGeometry& geometry, std::string method_name,
                       const MethodFactory& factory, MethodRebuilder rebuild)
    : scene_(scene), geometry_(&geometry), method_name_(std::move(method_name)), rebuild_(std::move(rebuild)) {
  // PETSc sums the ranks' shares of the matrices Newton hands it: no rank then holds the
  // whole Hessian (docs/scaling.md). Explicit steps and L-BFGS hand it none.
  ranks::share_matrices(scene.solver.linear == LinearSolverKind::petsc &&
                        scene.solver.nonlinear == NonlinearSolverKind::newton &&
                        (scene.time.is_static || scene.time.integrator != IntegratorKind::symplectic_euler));
  method_ = factory(scene, geometry);
  quadrature_seconds_ = method_->quadrature_seconds();
  scene_loads_ = scene_loads(scene, geometry, *method_, method_name_);
  layer_discretization(make_linear_solver(linear_solver_options(scene, *method_)));
  integrator_ = std::make_unique<TimeIntegrator>(*timed_, *linear_solver_, integrator_options(scene));
  check_static_supports(scene, *timed_);
  check_events();
  explicit_steps_ = !scene.time.is_static && scene.time.integrator == IntegratorKind::symplectic_euler;
  critical_time_step_ =
      explicit_steps_ ? estimate_critical_time_step(*timed_) : std::numeric_limits<double>::infinity();

  state_.displacement = Eigen::VectorXd::Zero(timed_->dof_count());
  state_.velocity = scene.time.is_static ? Eigen::VectorXd::Zero(timed_->dof_count()).eval()
                                         : initial_velocity(*method_, scene.initial);
  state_.time = scene.time.is_static ? 1.0 : 0.0;  // docs/scene-schema.md: statics evaluate motions at t = 1 s
  if (!scene.time.is_static) integrator_->apply_constraints(state_);
}

Simulation::~Simulation() = default;

LinearSolverStatistics Simulation::linear_statistics() const {
  LinearSolverStatistics total = retired_statistics_;
  add_statistics(total, linear_solver_->statistics());
  return total;
}

void Simulation::layer_discretization(std::unique_ptr<LinearSolver> solver) {
  // The integrator keeps pointing at the old layers (and solver) until it is rebound: build first.
  std::unique_ptr<ReleasedConditions> released =
      released_ ? std::make_unique<ReleasedConditions>(method_->discretization(), released_) : nullptr;
  const Discretization& base = released ? static_cast<const Discretization&>(*released) : method_->discretization();
  auto timed = std::make_unique<TimedDiscretization>(base, scene_loads_, assembly_seconds_);
  if (integrator_) integrator_->rebind(*timed, solver.get());
  if (solver) {
    if (linear_solver_) add_statistics(retired_statistics_, linear_solver_->statistics());
    linear_solver_ = std::move(solver);
  }
  released_layer_ = std::move(released);
  timed_ = std::move(timed);
}

// Every release must name a condition this method holds strongly, and every prefix of
// the releases must leave constraints the method can state: checked before the run
// writes anything, so a refused event is bad input (exit 2).
void Simulation::check_events() const {
  ConditionSet released = 0;
  for (const SceneEvent& event : scene_.events) {
    if (event.kind == EventKind::cut || event.kind == EventKind::refine) {
      const bool cut = event.kind == EventKind::cut;
      const std::string why = !rebuild_ ? "the run was built without the method's rebuild"
                              : cut     ? method_->cut_refusal()
                                        : method_->refine_refusal(event.refine);
      if (!why.empty())
        throw InputError(
            input_message(scene_.file.string(), event.pointer + (cut ? "/cut" : "/refine"),
                          std::string("cannot ") + (cut ? "cut" : "refine") + " with " + method_name_ + ": " + why));
      continue;
    }
    const std::string key = event.pointer + "/release";
    const DirichletCondition& condition = scene_.dirichlet[event.condition];
    const Discretization& discretization = method_->discretization();
    if (dofs_held_by(discretization, event.condition) == 0) {
      const std::string why =
          discretization.imposes_conditions_weakly()
              ? "this method imposes it weakly (terms of its energy, no constrained DOF): only a strongly imposed "
                "condition can be released (a method with both offers the choice in its discretization block)"
          : discretization.constraint_holders().empty() && !discretization.constrained_dofs().empty()
              ? "this method does not record which condition holds each constrained DOF"
              : "it holds no DOF of this method";
      throw InputError(input_message(scene_.file.string(), key,
                                     "cannot release '" + condition.name + "' (" + condition.pointer + "): " + why));
    }
    released |= condition_bit(event.condition);
    try {
      const ReleasedConditions check(discretization, released);
      if (scene_.time.is_static && check.constrained_dofs().empty())
        throw std::invalid_argument(
            "nothing would hold the body afterwards, and a static problem has no equilibrium "
            "without a support");
    } catch (const std::invalid_argument& error) {
      throw InputError(
          input_message(scene_.file.string(), key, "cannot release '" + condition.name + "': " + error.what()));
    }
  }
}

BodyMeasures Simulation::measure(EventRecord& record) {
  const auto start = std::chrono::steady_clock::now();
  if (!measure_basis_) measure_basis_ = body_measure_basis(*method_, *timed_);
  BodyMeasures measures = measure_body(*measure_basis_, *timed_, *integrator_, state_);
  record.seconds.measures += seconds_since(start);
  return measures;
}

EventRecord Simulation::start_record(std::string kind, std::string target, std::string pointer,
                                     double scheduled_time) const {
  EventRecord record;
  record.kind = std::move(kind);
  record.target = std::move(target);
  record.pointer = std::move(pointer);
  record.scheduled_time = scheduled_time;
  record.time = state_.time;
  record.step = state_.step;
  record.dofs_before = timed_->dof_count();
  record.constrained_before = static_cast<long long>(timed_->constrained_dofs().size());
  record.quadrature_points_before = method_->quadrature_points();
  return record;
}

void Simulation::finish_record(EventRecord& record, const BodyMeasures& before) {
  record.dofs_after = timed_->dof_count();
  record.constrained_after = static_cast<long long>(timed_->constrained_dofs().size());
  record.quadrature_points_after = method_->quadrature_points();
  record.conserved = conservation_json(before, measure(record));
}

EventRecord Simulation::apply(const SceneEvent& event) {
  if (event.kind == EventKind::cut) return cut(event);
  if (event.kind == EventKind::refine) return refine(event);
  const DirichletCondition& condition = scene_.dirichlet[event.condition];
  EventRecord record = start_record("release", condition.name, event.pointer, event.time);
  const BodyMeasures before = measure(record);
  // A release changes no basis and no integral: only the constrained set (the identity
  // transfer), so the only phase is the new elimination and Newton's set-up.
  const auto start = std::chrono::steady_clock::now();
  released_ |= condition_bit(event.condition);
  layer_discretization();
  if (explicit_steps_) critical_time_step_ = estimate_critical_time_step(*timed_);
  record.seconds.pattern = seconds_since(start);
  finish_record(record, before);
  return record;
}

EventRecord Simulation::rebuild() {
  const std::shared_ptr<const MethodMesh> mesh = method_->mesh();
  if (!rebuild_ || !mesh) throw std::logic_error("Simulation::rebuild: the method has no rebuild");
  EventRecord record = start_record("rebuild", "", "", state_.time);
  const BodyMeasures before = measure(record);
  rebuild_on(*mesh, record);
  finish_record(record, before);
  return record;
}

// The rest configuration cut by the blade (Kaufmann et al. 2009 §9.4, Martin et al. 2008
// §8): the method's mesh cut, the method rebuilt on it, the state transferred.
EventRecord Simulation::cut(const SceneEvent& event) {
  EventRecord record = start_record("cut", "", event.pointer, event.time);
  const BodyMeasures before = measure(record);
  auto start = std::chrono::steady_clock::now();
  // The surface every method deforms is cut by the same blade, so the frames show the body
  // open and `compare` still measures the same vertices. Neither cut reads the other's
  // result, nor does the method's rebuild read the surface (it deforms it from the first
  // frame after the event): the surface's cut (serial CGAL work) runs on a thread of its
  // own beside the method's cut and rebuild (whose loops are parallel), and the rebuilt
  // method adopts it. The geometry phase is the method's cut and the wait for the surface's.
  std::future<SurfaceCut> surface_cut;
  if (const SurfaceMesh* surface = geometry_->common_surface())
    surface_cut = std::async(std::launch::async, [surface, &event] { return cut_surface(*surface, event.blade); });
  {
    const CoreLentOut lent(surface_cut.valid());
    const std::shared_ptr<const MethodMesh> mesh = method_->cut_mesh(event, record.facts);
    record.seconds.geometry = seconds_since(start) - mesh->integration_seconds;
    rebuild_on(*mesh, record);
  }
  if (surface_cut.valid()) {
    start = std::chrono::steady_clock::now();
    SurfaceCut cut = surface_cut.get();
    record.facts["surface"] = std::move(cut.facts);
    SceneGeometry cut_geometry = *geometry_;
    (cut_geometry.surface ? cut_geometry.surface : cut_geometry.shape_surface) = std::move(cut.surface);
    cut_geometry_ = std::move(cut_geometry);
    geometry_ = &*cut_geometry_;
    method_->adopt_cut_surface(*geometry_->common_surface());
    record.seconds.geometry += seconds_since(start);
  }
  finish_record(record, before);
  return record;
}

// The rest configuration refined where the stress is high (Kaufmann et al. 2009 §9.3,
// Martin et al. 2008 §8): the marked cells split, the method rebuilt on the refined mesh,
// the state transferred. Nothing marked, nothing rebuilt.
EventRecord Simulation::refine(const SceneEvent& event) {
  EventRecord record = start_record("refine", "", event.pointer, event.time);
  const BodyMeasures before = measure(record);
  const auto start = std::chrono::steady_clock::now();
  const PrescribedTraction boundary(scene_, state_.time, region_tolerance(geometry_->bounds), released_);
  const std::shared_ptr<const MethodMesh> mesh =
      method_->refine_mesh(event, state_.displacement, boundary, record.facts);
  record.seconds.geometry = seconds_since(start) - (mesh ? mesh->integration_seconds : 0.0);
  if (mesh) rebuild_on(*mesh, record);
  finish_record(record, before);
  return record;
}

void Simulation::rebuild_on(const MethodMesh& mesh, EventRecord& record) {
  auto start = std::chrono::steady_clock::now();
  std::unique_ptr<MethodInstance> rebuilt = rebuild_(scene_, *geometry_, mesh);
  record.seconds.integration = seconds_since(start) + mesh.integration_seconds;
  quadrature_seconds_ += rebuilt->quadrature_seconds();

  start = std::chrono::steady_clock::now();
  Eigen::MatrixXd fields(state_.displacement.size(), 2);
  fields << state_.displacement, state_.velocity;
  const Eigen::MatrixXd moved = rebuilt->transfer(*method_, fields);
  State transferred = state_;
  transferred.displacement = moved.col(0);
  transferred.velocity = moved.col(1);
  record.seconds.transfer = seconds_since(start);

  start = std::chrono::steady_clock::now();
  rebuilt->continue_embedding(*method_);  // keys the old embedding while its elements are alive
  record.seconds.embedding = seconds_since(start);

  start = std::chrono::steady_clock::now();
  // The old method and its layers stay alive until the integrator is rebound.
  const std::unique_ptr<MethodInstance> previous = std::move(method_);
  method_ = std::move(rebuilt);
  measure_basis_.reset();
  scene_loads_ = scene_loads(scene_, *geometry_, *method_, method_name_);
  std::unique_ptr<LinearSolver> solver = make_linear_solver(linear_solver_options(scene_, *method_));
  layer_discretization(std::move(solver));
  if (explicit_steps_) critical_time_step_ = estimate_critical_time_step(*timed_);
  state_ = std::move(transferred);
  record.seconds.pattern = seconds_since(start);
}

}  // namespace altfem
