#pragma once
// What `altfem compare` keeps of one run: one row of results.csv (docs/conventions.md,
// "Metrics"); a completed run's folder holds its own one-row record.csv.
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

namespace altfem {

/// Wall seconds per phase, as in summary.json's "timings_s".
struct PhaseTimings {
  double setup = 0, quadrature = 0, assembly = 0, analysis = 0, factorisation = 0, solve = 0, total = 0;
};

struct RunRecord {
  // The configuration.
  std::string hash;  ///< run_hash of the resolved options: the folder runs/<hash>
  std::string method;
  std::string element;    ///< element type(s) of the run, "hex20" or "hex20+tet10"; "" if it failed early
  std::string label;      ///< "fem element=tet4 resolution=[10,1,1]"
  std::string overrides;  ///< the `--set` assignments, space separated
  bool is_reference = false;
  // How it ended.
  std::string status;   ///< "ok", "invalid input", "numerical failure", "internal error", "crashed", "interrupted"
  int exit_code = 0;    ///< the process's; 128 + signal when killed by one
  std::string message;  ///< the last line of its stderr when it failed
  // What it cost.
  long long dofs = 0, elements = 0, quadrature_points = 0, steps = 0, newton_iterations = 0, linear_iterations = 0;
  PhaseTimings timings;
  /// The scene's events (summary.json's `events`): how many acted, and their wall seconds
  /// per phase summed over them (cutting the mesh, integrating the rebuilt method,
  /// the new sparsity and solver, transferring the state).
  int events = 0;
  /// Of those, the refine events: a run that refined is an adaptive run, a series of its
  /// own in the report (beside the same method's uniform runs).
  int refinements = 0;
  double event_geometry_seconds = 0, event_integration_seconds = 0, event_pattern_seconds = 0,
         event_transfer_seconds = 0;
  double wall_seconds = 0;     ///< measured by compare around the process
  double peak_memory_mib = 0;  ///< wait4's ru_maxrss
  // How accurate it is: surface error against the reference run, over the reference's bounding-box diagonal.
  double rms_error = std::numeric_limits<double>::quiet_NaN();
  double max_error = std::numeric_limits<double>::quiet_NaN();
  /// The RMS surface error over the reference's RMS displacement (SurfaceError::relative_rms).
  double relative_rms_error = std::numeric_limits<double>::quiet_NaN();
  /// The scene's compare/error: the equal-accuracy table's target (in the measure the
  /// report ranks by: scripts/plot_report.py), kept in every row so
  /// that the report regenerates from results.csv alone (NaN: the report's default).
  double report_error = std::numeric_limits<double>::quiet_NaN();
  /// Against the scene's exact_displacement, when it has one (summary.json's
  /// field_errors): ‖u_h − u‖_L2 / ‖u‖_L2 and |u_h − u|_H1 / |u|_H1; NaN without.
  double field_l2_error = std::numeric_limits<double>::quiet_NaN();
  double field_h1_error = std::numeric_limits<double>::quiet_NaN();
  // Where it ran.
  std::string scene, date, cpu, blas;
  int cores = 0, threads = 0;

  bool ok() const { return status == "ok"; }
};

/// Fills the counts and timings from a run's summary.json (docs/conventions.md).
void add_summary(RunRecord& record, const nlohmann::json& summary);

}  // namespace altfem
