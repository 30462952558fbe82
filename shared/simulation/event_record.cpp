#include "shared/simulation/event_record.hpp"

#include <sstream>

namespace altfem {

nlohmann::json EventRecord::json() const {
  nlohmann::json result{
      {"kind", kind},
      {"target", target},
      {"time", time},
      {"scheduled_time", scheduled_time},
      {"step", step},
      {"dofs", {{"before", dofs_before}, {"after", dofs_after}}},
      {"constrained_dofs", {{"before", constrained_before}, {"after", constrained_after}}},
      {"quadrature_points", {{"before", quadrature_points_before}, {"after", quadrature_points_after}}},
      {"seconds",
       {{"geometry", seconds.geometry},
        {"integration", seconds.integration},
        {"pattern", seconds.pattern},
        {"transfer", seconds.transfer},
        {"embedding", seconds.embedding},
        {"measures", seconds.measures}}},
      {"conserved", conserved}};
  if (!pointer.empty()) result["pointer"] = pointer;
  if (!facts.is_null()) result["facts"] = facts;
  return result;
}

std::string EventRecord::log_line() const {
  std::ostringstream line;
  line << "# event " << kind;
  if (!target.empty()) line << " '" << target << "'";
  line << " at t = " << time << " after step " << step << ": dofs " << dofs_before << " -> " << dofs_after
       << ", constrained " << constrained_before << " -> " << constrained_after << "; seconds: geometry "
       << seconds.geometry << ", integration " << seconds.integration << ", pattern " << seconds.pattern
       << ", transfer " << seconds.transfer;
  if (!facts.is_null()) line << "; " << facts.dump();
  if (conserved.is_object())
    line << "; mass change " << conserved.value("mass_change", 0.0) << ", energy jump "
         << conserved.value("energy_jump_j", 0.0) << " J";
  return line.str();
}

}  // namespace altfem
