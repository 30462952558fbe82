#include "shared/simulation/run_simulation.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

#include "shared/common/error.hpp"
#include "shared/io/atomic_file.hpp"
#include "shared/io/json_file.hpp"
#include "shared/io/pvd_collection.hpp"
#include "shared/io/vtu_writer.hpp"
#include "shared/material/material.hpp"
#include "shared/simulation/event_schedule.hpp"
#include "shared/simulation/field_errors.hpp"
#include "shared/simulation/progress.hpp"
#include "shared/simulation/simulation.hpp"
#include "shared/solve/blas_info.hpp"
#include "shared/solve/process_ranks.hpp"

namespace altfem {

namespace {

// The state after a step must be finite and bounded: an explicit step above the
// stability limit, or a diverging solve, is stopped at the first such step (exit 3)
// before anything non-finite reaches an output file.
void check_state(const State& state, double total_energy, double size, int step, double time_step,
                 double critical_time_step) {
  const bool finite = state.displacement.allFinite() && state.velocity.allFinite() && std::isfinite(total_energy);
  const double largest = finite ? state.displacement.cwiseAbs().maxCoeff() : 0.0;
  if (finite && largest <= 1e6 * size) return;
  std::ostringstream message;
  message << "step " << step << ": the state ";
  if (finite) message << "exploded (displacement " << largest << " m, over 1e6 times the body's size " << size << " m)";
  else message << "is not finite";
  if (std::isfinite(critical_time_step) && time_step > critical_time_step)
    message << "; the time step " << time_step << " s exceeds the explicit stability limit, about "
            << critical_time_step << " s: reduce time.dt or use an implicit integrator";
  throw NumericalError(message.str());
}

// Near incompressibility (ν ≥ 0.49): the tangent's condition number grows like λ/μ, so
// residuals stall at round-off, and low-order elements lock. `stopped`: Newton stopped at
// the round-off floor (a warning of its own) rather than failed (appended to the error).
std::string near_incompressible_hint(const Scene& scene, bool stopped = false) {
  const double nu = scene.material.poisson_ratio;
  if (nu < 0.49) return "";
  std::ostringstream hint;
  hint << std::setprecision(8) << "at Poisson's ratio " << nu << " (λ/μ = " << 2 * nu / (1 - 2 * nu) << ") ";
  if (stopped)
    hint << "the tangent is ill-conditioned and residuals stopped at the round-off floor of the assembled forces; "
            "low-order elements lock: use a higher-order element or a locking-free discretization";
  else
    hint << "the tangent is ill-conditioned and residuals stall at round-off: use a higher-order element, a looser "
            "solver.tolerance, or a locking-free discretization";
  return stopped ? hint.str() : " — " + hint.str();
}

// After a failure: when the last converged state's stresses passed the smallest Young's
// modulus of a model with no barrier against inverting elements (resists_inversion), its
// strains were past 100 %, elements may be crushed through inversion, where Newton stalls
// at a kink of the energy and no smaller step helps (issue #35: a 100 Pa corotated bar
// under its weight, 1.5e8 Pa at t = 1.1 s).
std::string large_strain_hint(const Scene& scene, double max_von_mises) {
  const MaterialSpec* weakest = nullptr;
  for (const MaterialSpec& material : scene.materials)
    if (!resists_inversion(material_model_from_name(material.model).value()) &&
        (!weakest || material.youngs_modulus < weakest->youngs_modulus))
      weakest = &material;
  if (!weakest || !(max_von_mises > weakest->youngs_modulus)) return "";
  std::ostringstream hint;
  hint << std::setprecision(3) << " — the last converged state's von Mises stress was "
       << max_von_mises / weakest->youngs_modulus << " times " << weakest->pointer
       << "'s Young's modulus (strains past 100 %), and '" << weakest->model
       << "' has no barrier against inverting elements: use stable_neo_hookean";
  return hint.str();
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The largest von Mises stress of the elements' mean Cauchy stresses (#elements × 9);
// 0 when there are none.
Eigen::VectorXd von_mises(const Eigen::MatrixXd& stresses) {
  Eigen::VectorXd result(stresses.rows());
  for (Eigen::Index e = 0; e < stresses.rows(); ++e) {
    const Eigen::RowVectorXd row = stresses.row(e);  // contiguous: rows of a column-major matrix are strided
    const Eigen::Matrix3d sigma = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(row.data());
    const Eigen::Matrix3d deviator = sigma - sigma.trace() / 3 * Eigen::Matrix3d::Identity();
    result[e] = std::sqrt(1.5 * deviator.squaredNorm());  // √(3/2 s:s)
  }
  return result;
}

double max_von_mises(const Discretization& discretization, const Eigen::VectorXd& displacement) {
  const Eigen::MatrixXd stresses = discretization.element_cauchy_stress(displacement);
  return stresses.rows() == 0 ? 0.0 : von_mises(stresses).maxCoeff();
}

// summary.json's field_errors of the final state against the scene's exact_displacement,
// on a rule 2 stronger than the method's own where it can (field_quadrature); null for a
// method that cannot tabulate its basis at points.
nlohmann::json exact_solution_errors(const MethodInstance& method, const VectorExpression& exact, const State& state) {
  const std::optional<FieldQuadrature> quadrature = method.field_quadrature(2);
  if (!quadrature) return nullptr;
  return field_errors_json(field_errors(*quadrature, exact, state.displacement, state.time));
}

// Writes the frames of one output time: the method's mesh and the embedded surface.
// After an event the frames carry the new mesh (the method the simulation holds then);
// the embedded surface keeps its vertices, so surface errors stay defined.
class FrameWriter {
public:
  FrameWriter(const Simulation& simulation, const std::filesystem::path& directory, const OutputSpec& output,
              FrameObserver observer)
      : simulation_(simulation),
        directory_(directory),
        output_(output),
        volume_(directory / "volume.pvd"),
        surface_(directory / "surface.pvd"),
        observer_(std::move(observer)) {}

  // Stress as cell data, when the discretization's elements are the volume cells.
  static void add_stress(UnstructuredGrid& grid, const Eigen::MatrixXd& stresses) {
    if (stresses.rows() == 0 || stresses.rows() != grid.cell_count()) return;
    grid.cell_data.emplace_back("cauchy_stress", stresses);
    grid.cell_data.emplace_back("von_mises", von_mises(stresses));
  }

  void write(const Eigen::VectorXd& displacement, double time) {
    // Every rank computes its elements' stresses, which their sum over the ranks makes whole.
    const Eigen::MatrixXd stresses =
        output_.volume ? simulation_.discretization().element_cauchy_stress(displacement) : Eigen::MatrixXd();
    if (ranks::index() != 0) return;  // rank 0 writes every frame
    char name[64];
    RunFrame frame;
    frame.time = time;
    if (output_.volume) {
      std::snprintf(name, sizeof name, "volume_%06d.vtu", frame_);
      frame.volume = simulation_.method().volume_grid(displacement);
      add_stress(frame.volume, stresses);
      write_vtu(directory_ / name, frame.volume);
      volume_.add(time, name);
      volume_.write();
    }
    if (output_.surface) {
      std::snprintf(name, sizeof name, "surface_%06d.vtu", frame_);
      const SurfaceMesh& surface = simulation_.method().embedded_surface();
      frame.surface_displacement = simulation_.method().embedded_displacement(displacement);
      UnstructuredGrid grid;
      grid.points = surface.vertices + frame.surface_displacement;
      grid.add_triangles(surface.triangles);
      grid.point_data.emplace_back("displacement", frame.surface_displacement);
      write_vtu(directory_ / name, grid);
      surface_.add(time, name);
      surface_.write();
      last_surface_ = directory_ / name;
      if (observer_) {
        frame.surface_vertices = surface.vertices;
        frame.surface_triangles = surface.triangles;
      }
    }
    if (observer_) observer_(std::move(frame));
    ++frame_;
  }
  const std::filesystem::path& last_surface() const { return last_surface_; }

private:
  const Simulation& simulation_;
  std::filesystem::path directory_;
  OutputSpec output_;
  PvdCollection volume_, surface_;
  std::filesystem::path last_surface_;
  FrameObserver observer_;
  int frame_ = 0;
};

}  // namespace

nlohmann::json run_simulation(const Scene& scene, const SceneGeometry& geometry, const std::string& method_name,
                              const MethodFactory& factory, const std::filesystem::path& output_directory,
                              double setup_seconds) {
  return run_simulation(scene, geometry, method_name, MethodDescription{.factory = factory}, output_directory,
                        setup_seconds);
}

nlohmann::json run_simulation(const Scene& scene, const SceneGeometry& geometry, const std::string& method_name,
                              const MethodDescription& description, const std::filesystem::path& output_directory,
                              double setup_seconds, const FrameObserver& on_frame) {
  const auto start = std::chrono::steady_clock::now();
  const double loading_seconds = setup_seconds;
  Simulation simulation(scene, geometry, method_name, description.factory, description.rebuild);
  const MethodInstance& method = simulation.method();
  const double critical_time_step = simulation.critical_time_step();
  // Over several processes rank 0 alone writes and warns (every rank holds the same state).
  const bool reports = ranks::index() == 0;
  if (reports && simulation.explicit_steps() && scene.time.dt > critical_time_step)
    std::fprintf(stderr,
                 "altfem: warning: time.dt = %g s exceeds the explicit stability limit, about %.3g s (2/omega_max, "
                 "omega_max^2 the largest eigenvalue of M^-1 K at rest): symplectic Euler will diverge\n",
                 scene.time.dt, critical_time_step);
  setup_seconds += seconds_since(start);

  if (reports) std::filesystem::create_directories(output_directory);
  std::ostringstream log;
  nlohmann::json summary;
  summary["scene"] = scene.name;
  summary["method"] = method_name;
  summary["options"] = scene.resolved;
  const BlasInfo blas = loaded_blas();
  const char* wait_policy = std::getenv("OMP_WAIT_POLICY");
  summary["environment"] = {{"threads", omp_get_max_threads()},
                            {"openmp_wait_policy", wait_policy != nullptr ? wait_policy : "libgomp's default"},
                            {"blas", blas.implementation}};
  if (reports && is_reference_blas(blas))
    std::fprintf(stderr,
                 "altfem: warning: the reference BLAS is loaded (%s): CHOLMOD runs ~10x slower; "
                 "install libopenblas0-pthread\n",
                 blas.library.c_str());
  summary["facts"] = method.facts();
  summary["warnings"] = method.warnings();
  if (ranks::distributed() && scene.solver.linear != LinearSolverKind::petsc) {
    const std::string warning = "with " + std::to_string(ranks::count()) + " ranks, solver.linear \"" +
                                std::string(linear_solver_kind_name(scene.solver.linear)) +
                                "\" solves the whole system on every rank; \"petsc\" solves it across them";
    summary["warnings"].push_back(warning);
    if (reports) std::fprintf(stderr, "altfem: warning: %s\n", warning.c_str());
  }
  if (reports)
    for (const std::string& warning : method.warnings()) std::fprintf(stderr, "altfem: warning: %s\n", warning.c_str());
  if (simulation.explicit_steps()) summary["facts"]["critical_time_step"] = critical_time_step;

  State& state = simulation.state();
  FrameWriter frames(simulation, output_directory, scene.output, on_frame);
  EventSchedule events(scene, simulation, log);
  // A static scene's refinement cycles re-solve at the full load after its last load step,
  // one solve per cycle (events at times load_steps, load_steps + 1, …; scene_events.cpp).
  const int cycles = scene.time.is_static ? static_cast<int>(std::count_if(scene.events.begin(), scene.events.end(),
                                                                           [&](const SceneEvent& event) {
                                                                             return event.time >= scene.time.load_steps;
                                                                           }))
                                          : 0;
  const int steps = scene.time.is_static ? scene.time.load_steps + cycles : scene.time.steps;
  long long newton_iterations = 0, lbfgs_evaluations = 0, linear_iterations = 0;
  int cutbacks = 0, round_off_stops = 0;
  double smallest_increment = 1;
  const double size = geometry.bounds.diagonal().norm();
  std::string status = "ok";
  Progress progress(steps);
  int steps_done = 0;
  try {
    frames.write(state.displacement, scene.time.is_static ? 0.0 : state.time);
    // iterations: Newton iterations, or objective evaluations with solver.nonlinear = lbfgs;
    // time: a static run's load factor.
    log << "# step time dofs iterations linear_iterations residual total_energy max_von_mises\n";
    events.apply_due(scene.time.is_static ? 0.0 : state.time);
    for (int step = 1; step <= steps; ++step) {
      if (scene.time.is_static) state.load_factor = std::min(1.0, static_cast<double>(step) / scene.time.load_steps);
      StepReport report;
      try {
        report = simulation.integrator().step(state);
      } catch (const NumericalError&) {
        const StepReport failed = simulation.integrator().failed_step_report();
        newton_iterations += failed.newton_iterations;
        lbfgs_evaluations += failed.lbfgs_evaluations;
        linear_iterations += failed.linear_iterations;
        throw;
      }
      newton_iterations += report.newton_iterations;
      lbfgs_evaluations += report.lbfgs_evaluations;
      linear_iterations += report.linear_iterations;
      if (report.cutbacks > 0) {
        cutbacks += report.cutbacks;
        smallest_increment = std::min(smallest_increment, report.smallest_increment);
        log << "# cutback step " << step << ": " << report.cutbacks << " failed attempt"
            << (report.cutbacks == 1 ? "" : "s") << ", smallest increment " << report.smallest_increment
            << " of the step\n";
      }
      if (report.round_off_floor > 0) {
        ++round_off_stops;
        log << "# round-off step " << step << ": residual " << report.residual << " above the tolerance, below "
            << report.round_off_floor << ", the round-off floor of the assembled forces\n";
      }
      const double total_energy = simulation.integrator().total_energy(state);
      check_state(state, total_energy, size, step, scene.time.dt, simulation.critical_time_step());
      steps_done = step;
      // A static frame's time is the load factor, and beyond 1 counts the refinement cycles.
      const double time = scene.time.is_static ? static_cast<double>(step) / scene.time.load_steps : state.time;
      log << step << ' ' << time << ' ' << simulation.discretization().dof_count() << ' '
          << report.newton_iterations + report.lbfgs_evaluations << ' ' << report.linear_iterations << ' '
          << report.residual << ' ' << total_energy << ' '
          << max_von_mises(simulation.discretization(), state.displacement) << '\n';
      if (step % scene.output.every == 0 || step == steps) {
        frames.write(state.displacement, time);
        events.add_embedding_report();
      }
      progress.update(step, report.newton_iterations);
      events.apply_due(scene.time.is_static ? step : state.time);
    }
  } catch (const NumericalError& error) {
    // The state is the last converged one (a step, or an increment of the failed step).
    status = std::string("error: ") + error.what() + near_incompressible_hint(scene) +
             large_strain_hint(scene, max_von_mises(simulation.discretization(), state.displacement)) +
             simulation.method().failure_hint();
  }

  if (round_off_stops > 0) {
    if (const std::string hint = near_incompressible_hint(scene, true); !hint.empty()) {
      if (reports) std::fprintf(stderr, "altfem: warning: %s\n", hint.c_str());
      summary["warnings"].push_back(hint);
    }
  }
  if (const int whole = events.surface_pieces_left_whole(); whole > 0) {
    const std::string warning =
        std::to_string(whole) +
        " time(s) a cut left a piece of the deformed surface uncut: its earlier cuts made it intersect itself (a "
        "notch's caps on one another, or many cuts through one place), which CGAL's corefinement cannot cut; the "
        "volume was cut, that piece of the surface was not, and its vertices move with the side each lies in";
    if (reports) std::fprintf(stderr, "altfem: warning: %s\n", warning.c_str());
    summary["warnings"].push_back(warning);
  }
  const LinearSolverStatistics statistics = simulation.linear_statistics();
  const double total = loading_seconds + seconds_since(start);
  summary["timings_s"] = {{"setup", setup_seconds},
                          {"quadrature", simulation.quadrature_seconds()},
                          {"assembly", simulation.assembly_seconds()},
                          {"analysis", statistics.analysis_seconds},
                          {"factorisation", statistics.factorisation_seconds},
                          {"solve", statistics.solve_seconds},
                          {"total", total}};
  summary["counts"] = {{"analyses", statistics.analyses}, {"factorisations", statistics.factorisations}};
  // Over several processes, each phase's seconds on every rank (rank order): how evenly
  // the element partition shared the assembly, and what the solve cost each.
  if (ranks::distributed())
    summary["ranks"] = {{"count", ranks::count()},
                        {"timings_s",
                         {{"quadrature", ranks::gather(simulation.quadrature_seconds())},
                          {"assembly", ranks::gather(simulation.assembly_seconds())},
                          {"analysis", ranks::gather(statistics.analysis_seconds)},
                          {"factorisation", ranks::gather(statistics.factorisation_seconds)},
                          {"solve", ranks::gather(statistics.solve_seconds)},
                          {"total", ranks::gather(total)}}}};
  // What blas_thread_choice.hpp chose for the factorisations (issue #35); the solves ran on one.
  if (statistics.most_blas_threads > 0)
    summary["environment"]["factorisation_blas_threads"] = {{"fewest", statistics.fewest_blas_threads},
                                                            {"most", statistics.most_blas_threads},
                                                            {"flops", statistics.factorisation_flops}};
  // The discretization after the last event (each event records its own change).
  summary["dofs"] = simulation.discretization().dof_count();
  summary["constrained_dofs"] = simulation.discretization().constrained_dofs().size();
  summary["elements"] = simulation.method().element_counts();
  summary["quadrature_points"] = simulation.method().quadrature_points();
  // `facts` are the method's at the start; after events the one that ran last has its own.
  if (!events.records().empty()) summary["facts_at_end"] = simulation.method().facts();
  summary["steps"] = steps_done;
  summary["newton_iterations"] = newton_iterations;
  if (scene.solver.nonlinear == NonlinearSolverKind::lbfgs) summary["lbfgs_evaluations"] = lbfgs_evaluations;
  summary["linear_iterations"] = linear_iterations;
  summary["cutbacks"] = {{"failed_attempts", cutbacks}, {"smallest_increment", smallest_increment}};
  summary["round_off_stops"] = round_off_stops;
  summary["events"] = events.records();
  summary["status"] = status;
  summary["surface"] = frames.last_surface().empty() ? "" : frames.last_surface().filename().string();
  if (scene.exact_displacement.has_value() && status == "ok")
    summary["field_errors"] = exact_solution_errors(simulation.method(), scene.exact_displacement, state);
  if (reports) {
    write_file_atomically(output_directory / "log.txt", log.str());
    write_json_file(output_directory / "summary.json", summary);
  }
  if (status != "ok") throw NumericalError(status.substr(std::string("error: ").size()));
  return summary;
}

}  // namespace altfem
