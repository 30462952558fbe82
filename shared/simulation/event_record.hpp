#pragma once
// What one event did to a run (docs/conventions.md, "Command line and outputs"): a line
// of log.txt and an entry of summary.json's `events`.
#include <nlohmann/json.hpp>
#include <string>

namespace altfem {

/// Seconds an event spent, by phase: cutting or refining the geometry, re-integrating
/// (quadrature, bases), building the new system (assembly pattern, solver, integrator),
/// transferring the state, and embedding the surface in the new basis: keying the old
/// embedding for the new one here, and the new one built on first use, by the first
/// surface frame after the event, which the run adds to the event's `seconds` in
/// summary.json then; and measuring the body before and after for what the event
/// conserved (after it, in the new basis: its mass and momentum functionals).
struct EventPhases {
  double geometry = 0;
  double integration = 0;
  double pattern = 0;
  double transfer = 0;
  double embedding = 0;
  double measures = 0;
};

struct EventRecord {
  std::string kind;           ///< "release", "rebuild", …
  std::string target;         ///< what it acted on (a condition's name)
  std::string pointer;        ///< the scene key, "/events/i"; empty for an event not from the scene
  double scheduled_time = 0;  ///< the event's `time`
  double time = 0;            ///< the state's time when it acted
  int step = 0;               ///< the steps done before it acted
  long long dofs_before = 0, dofs_after = 0;
  long long constrained_before = 0, constrained_after = 0;
  long long quadrature_points_before = 0, quadrature_points_after = 0;
  EventPhases seconds;
  nlohmann::json conserved;  ///< conservation_json (body_measures.hpp)
  nlohmann::json facts;      ///< what the event did, by kind (a cut's counts); null when nothing

  nlohmann::json json() const;
  /// One line for log.txt, starting with "# event" (a comment to the step table's readers).
  std::string log_line() const;
};

}  // namespace altfem
