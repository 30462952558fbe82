#include "shared/simulation/run_simulation.hpp"

#include <omp.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "shared/common/error.hpp"
#include "shared/io/atomic_file.hpp"
#include "shared/io/json_file.hpp"
#include "shared/io/pvd_collection.hpp"
#include "shared/io/vtu_writer.hpp"
#include "shared/simulation/progress.hpp"
#include "shared/simulation/rigid_motion.hpp"
#include "shared/simulation/timed_discretization.hpp"
#include "shared/solve/blas_info.hpp"
#include "shared/solve/time_integrator.hpp"

namespace altfem {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

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
  options.project_spd = scene.solver.project_spd;
  options.rayleigh_mass = scene.time.rayleigh_mass;
  options.rayleigh_stiffness = scene.time.rayleigh_stiffness;
  options.gravity = scene.gravity;
  return options;
}

LinearSolverOptions linear_solver_options(const Scene& scene, const Discretization& discretization) {
  LinearSolverOptions options;
  options.kind = scene.solver.linear;
  options.preconditioner = scene.solver.preconditioner;
  options.custom_preconditioner = discretization.preconditioner_factory();
  options.tolerance = scene.solver.linear_tolerance;
  options.max_iterations = scene.solver.linear_max_iterations;
  return options;
}

// Writes the frames of one output time: the method's mesh and the embedded surface.
class FrameWriter {
public:
  FrameWriter(const MethodInstance& method, const std::filesystem::path& directory, const OutputSpec& output)
      : method_(method), directory_(directory), output_(output), volume_(directory / "volume.pvd"),
        surface_(directory / "surface.pvd") {}

  void write(const Eigen::VectorXd& displacement, double time) {
    char name[64];
    if (output_.volume) {
      std::snprintf(name, sizeof name, "volume_%06d.vtu", frame_);
      write_vtu(directory_ / name, method_.volume_grid(displacement));
      volume_.add(time, name);
      volume_.write();
    }
    if (output_.surface) {
      std::snprintf(name, sizeof name, "surface_%06d.vtu", frame_);
      const SurfaceMesh& surface = method_.embedded_surface();
      const Eigen::MatrixXd moved = method_.embedded_displacement(displacement);
      UnstructuredGrid grid;
      grid.points = surface.vertices + moved;
      grid.add_triangles(surface.triangles);
      grid.point_data.emplace_back("displacement", moved);
      write_vtu(directory_ / name, grid);
      surface_.add(time, name);
      surface_.write();
      last_surface_ = directory_ / name;
    }
    ++frame_;
  }
  const std::filesystem::path& last_surface() const { return last_surface_; }

private:
  const MethodInstance& method_;
  std::filesystem::path directory_;
  OutputSpec output_;
  PvdCollection volume_, surface_;
  std::filesystem::path last_surface_;
  int frame_ = 0;
};

}  // namespace

nlohmann::json run_simulation(const Scene& scene, const SceneGeometry& geometry, const std::string& method_name,
                              const MethodFactory& factory, const std::filesystem::path& output_directory,
                              double setup_seconds) {
  const auto start = std::chrono::steady_clock::now();
  const double loading_seconds = setup_seconds;
  const std::unique_ptr<MethodInstance> method = factory(scene, geometry);
  const TimedDiscretization discretization(method->discretization());
  const auto linear_solver = make_linear_solver(linear_solver_options(scene, discretization));
  TimeIntegrator integrator(discretization, *linear_solver, integrator_options(scene));
  setup_seconds += seconds_since(start);

  std::filesystem::create_directories(output_directory);
  std::ostringstream log;
  nlohmann::json summary;
  summary["scene"] = scene.name;
  summary["method"] = method_name;
  summary["options"] = scene.resolved;
  summary["dofs"] = discretization.dof_count();
  summary["constrained_dofs"] = discretization.constrained_dofs().size();
  summary["elements"] = method->element_counts();
  summary["quadrature_points"] = {{"initial", method->quadrature_points()}, {"final", method->quadrature_points()}};
  const BlasInfo blas = loaded_blas();
  summary["environment"] = {{"threads", omp_get_max_threads()}, {"blas", blas.implementation}};
  if (is_reference_blas(blas))
    std::fprintf(stderr, "altfem: warning: the reference BLAS is loaded (%s): CHOLMOD runs ~10x slower; "
                         "install libopenblas0-pthread\n", blas.library.c_str());
  summary["facts"] = method->facts();

  State state;
  state.displacement = Eigen::VectorXd::Zero(discretization.dof_count());
  state.velocity = scene.time.is_static ? Eigen::VectorXd::Zero(discretization.dof_count()).eval()
                                        : initial_velocity(*method, scene.initial);
  state.time = scene.time.is_static ? 1.0 : 0.0;  // docs/scene-schema.md: statics evaluate motions at t = 1 s
  if (!scene.time.is_static) integrator.apply_constraints(state);

  FrameWriter frames(*method, output_directory, scene.output);
  const int steps = scene.time.is_static ? 1 : scene.time.steps;
  long long newton_iterations = 0, linear_iterations = 0;
  std::string status = "ok";
  Progress progress(steps);
  int steps_done = 0;
  try {
    frames.write(state.displacement, scene.time.is_static ? 0.0 : state.time);
    log << "# step time newton_iterations linear_iterations residual total_energy\n";
    for (int step = 1; step <= steps; ++step) {
      const StepReport report = integrator.step(state);
      newton_iterations += report.newton_iterations;
      linear_iterations += report.linear_iterations;
      steps_done = step;
      log << step << ' ' << state.time << ' ' << report.newton_iterations << ' ' << report.linear_iterations << ' '
          << report.residual << ' ' << integrator.total_energy(state) << '\n';
      if (step % scene.output.every == 0 || step == steps) frames.write(state.displacement, state.time);
      progress.update(step, report.newton_iterations);
    }
  } catch (const NumericalError& error) {
    status = std::string("error: ") + error.what();
  }

  const LinearSolverStatistics& statistics = linear_solver->statistics();
  const double total = loading_seconds + seconds_since(start);
  summary["timings_s"] = {{"setup", setup_seconds},
                          {"quadrature", method->quadrature_seconds()},
                          {"assembly", discretization.assembly_seconds()},
                          {"analysis", statistics.analysis_seconds},
                          {"factorisation", statistics.factorisation_seconds},
                          {"solve", statistics.solve_seconds},
                          {"total", total}};
  summary["counts"] = {{"analyses", statistics.analyses}, {"factorisations", statistics.factorisations}};
  summary["steps"] = steps_done;
  summary["newton_iterations"] = newton_iterations;
  summary["linear_iterations"] = linear_iterations;
  summary["status"] = status;
  summary["surface"] = frames.last_surface().empty() ? "" : frames.last_surface().filename().string();
  write_file_atomically(output_directory / "log.txt", log.str());
  write_json_file(output_directory / "summary.json", summary);
  if (status != "ok") throw NumericalError(status.substr(std::string("error: ").size()));
  return summary;
}

}  // namespace altfem
