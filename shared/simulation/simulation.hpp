#pragma once
// What a run builds from a scene and a method, as one object that events rebuild
// (docs/architecture.md, "Events"): the method, the scene's loads in its basis, the
// layers the run puts over its discretization (released conditions, timing and scene
// loads), the linear solver, the integrator, the explicit stability limit and the state.
// An event changes what it must and keeps the state, the step count and the counters.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "shared/scene/scene.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/simulation/body_measures.hpp"
#include "shared/simulation/event_record.hpp"
#include "shared/simulation/method_instance.hpp"
#include "shared/simulation/timed_discretization.hpp"
#include "shared/solve/linear_solver.hpp"
#include "shared/solve/released_conditions.hpp"
#include "shared/solve/time_integrator.hpp"

namespace altfem {

class Simulation {
public:
  /// Builds the method (`factory`) and everything the run needs; `rebuild` (may be
  /// empty) is the method's build from a handed mesh, for events that change it.
  /// Throws InputError for what the scene asks and the method cannot do, the scene's
  /// events included, before anything is written.
  Simulation(const Scene& scene, const SceneGeometry& geometry, std::string method_name, const MethodFactory& factory,
             MethodRebuilder rebuild = {});
  ~Simulation();

  const MethodInstance& method() const { return *method_; }
  /// The run's view of the method's discretization (released conditions, scene loads, timing).
  const Discretization& discretization() const { return *timed_; }
  TimeIntegrator& integrator() { return *integrator_; }
  const TimeIntegrator& integrator() const { return *integrator_; }
  State& state() { return state_; }
  const State& state() const { return state_; }
  /// Symplectic Euler's stability limit; +∞ for the other schemes.
  double critical_time_step() const { return critical_time_step_; }
  bool explicit_steps() const { return explicit_steps_; }
  /// The linear solvers' counters over the whole run (events included).
  LinearSolverStatistics linear_statistics() const;
  /// Seconds of energy, gradient and Hessian evaluations over the whole run.
  double assembly_seconds() const { return assembly_seconds_; }
  /// Seconds of quadrature (tabulation) over the whole run, the first set-up included.
  double quadrature_seconds() const { return quadrature_seconds_; }

  /// Applies a scene event to the state.
  EventRecord apply(const SceneEvent& event);
  /// Rebuilds the method on the mesh it was built on (an event that changes nothing:
  /// the conformance suite's no-op, and the bench's rebuild cost) and transfers the
  /// state. Throws std::logic_error for a method without a rebuild.
  EventRecord rebuild();

private:
  void check_events() const;
  EventRecord cut(const SceneEvent& event);
  EventRecord refine(const SceneEvent& event);
  // The method rebuilt on `mesh` and the state transferred to it (its phases into `record`).
  void rebuild_on(const MethodMesh& mesh, EventRecord& record);
  // The layers over the method's discretization for the conditions released so far, and
  // the integrator rebound to them; with `solver`, it replaces the linear solver (a new
  // method brings its own preconditioner).
  void layer_discretization(std::unique_ptr<LinearSolver> solver = nullptr);
  EventRecord start_record(std::string kind, std::string target, std::string pointer, double scheduled_time) const;
  // The body's measures now, their seconds added to `record`'s; the basis of them is
  // measured once per method.
  BodyMeasures measure(EventRecord& record);
  void finish_record(EventRecord& record, const BodyMeasures& before);

  const Scene& scene_;
  // The scene's geometry, or after a cut `cut_geometry_`: its copy with the common surface
  // cut too (cut_surface), which the methods rebuilt after the cut deform.
  const SceneGeometry* geometry_;
  std::optional<SceneGeometry> cut_geometry_;
  std::string method_name_;
  MethodRebuilder rebuild_;
  std::unique_ptr<MethodInstance> method_;
  std::vector<TimeDependentLoad> scene_loads_;
  ConditionSet released_ = 0;
  std::unique_ptr<ReleasedConditions> released_layer_;
  std::unique_ptr<TimedDiscretization> timed_;
  std::unique_ptr<LinearSolver> linear_solver_;
  LinearSolverStatistics retired_statistics_;  // of the solvers events replaced
  std::unique_ptr<TimeIntegrator> integrator_;
  bool explicit_steps_ = false;
  double critical_time_step_ = 0;
  double assembly_seconds_ = 0;
  double quadrature_seconds_ = 0;
  std::optional<BodyMeasureBasis> measure_basis_;  // of method_, once an event needs it
  State state_;
};

/// The linear solver the scene's `solver` block chooses (kind, its preconditioner — the
/// method's own when it has one — tolerance and iteration limit; for `petsc` its options
/// and the method's rigid-body modes).
LinearSolverOptions linear_solver_options(const Scene& scene, const MethodInstance& method);

/// The integrator the scene's `time` and `solver` blocks choose.
IntegratorOptions integrator_options(const Scene& scene);

}  // namespace altfem
