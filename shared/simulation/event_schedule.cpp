#include "shared/simulation/event_schedule.hpp"

#include <sstream>

#include "shared/common/error.hpp"

namespace altfem {

EventSchedule::EventSchedule(const Scene& scene, Simulation& simulation, std::ostringstream& log)
    : events_(scene.events),
      simulation_(simulation),
      log_(log),
      tolerance_(scene.time.is_static ? 0.0 : 1e-9 * scene.time.dt) {}

void EventSchedule::apply_due(double now) {
  while (next_ < events_.size() && events_[next_].time <= now + tolerance_) {
    const MethodInstance* before = &simulation_.method();
    const SceneEvent& event = events_[next_++];
    EventRecord record;
    try {
      record = simulation_.apply(event);
    } catch (const NumericalError& error) {  // where: the event, then what failed in it
      std::ostringstream where;
      where << event.pointer << " (t = " << event.time << "): " << error.what();
      throw NumericalError(where.str());
    }
    log_ << record.log_line() << '\n';
    records_.push_back(record.json());
    if (&simulation_.method() != before) unembedded_ = records_.size() - 1;
  }
}

void EventSchedule::add_embedding_report() {
  if (!unembedded_) return;
  const nlohmann::json report = simulation_.method().surface_embedding_report();
  if (report.is_null()) return;
  nlohmann::json& record = records_[*unembedded_];
  record["seconds"]["embedding"] = record["seconds"]["embedding"].get<double>() + report["seconds"].get<double>();
  record["facts"]["surface"]["vertices_relocated"] = report["vertices_relocated"];
  unembedded_.reset();
}

int EventSchedule::surface_pieces_left_whole() const {
  const nlohmann::json::json_pointer whole("/facts/surface/pieces_left_whole");
  int count = 0;
  for (const nlohmann::json& record : records_)
    if (record.contains(whole)) count += record[whole].get<int>();
  return count;
}

}  // namespace altfem
