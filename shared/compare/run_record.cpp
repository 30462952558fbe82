#include "shared/compare/run_record.hpp"

namespace altfem {

using nlohmann::json;

void add_summary(RunRecord& record, const json& summary) {
  record.dofs = summary.at("dofs");
  record.element.clear();
  record.elements = 0;
  for (const auto& [type, count] : summary.at("elements").items()) {
    record.element += (record.element.empty() ? "" : "+") + type;
    record.elements += count.get<long long>();
  }
  record.quadrature_points = summary.at("quadrature_points");
  record.steps = summary.at("steps");
  record.newton_iterations = summary.at("newton_iterations");
  record.linear_iterations = summary.at("linear_iterations");
  const auto& t = summary.at("timings_s");
  record.timings = {t.at("setup"),         t.at("quadrature"), t.at("assembly"), t.at("analysis"),
                    t.at("factorisation"), t.at("solve"),      t.at("total")};
  record.events = record.refinements = 0;
  record.event_geometry_seconds = record.event_integration_seconds = 0;
  record.event_pattern_seconds = record.event_transfer_seconds = 0;
  for (const json& event : summary.value("events", json::array())) {
    ++record.events;
    if (event.value("kind", "") == "refine") ++record.refinements;
    const json& seconds = event.at("seconds");
    record.event_geometry_seconds += seconds.at("geometry").get<double>();
    record.event_integration_seconds += seconds.at("integration").get<double>();
    record.event_pattern_seconds += seconds.at("pattern").get<double>();
    record.event_transfer_seconds += seconds.at("transfer").get<double>();
  }
  if (summary.contains("field_errors")) {
    record.field_l2_error = summary["field_errors"].at("relative_l2");
    record.field_h1_error = summary["field_errors"].at("relative_h1_seminorm");
  }
}

}  // namespace altfem
