#pragma once
// The scene's events in time order, applied as the run reaches them (run_simulation): a
// dynamic event at the first step boundary at or after its time, a static one after its
// load step; each a line of log.txt and a record of summary.json's `events`, to which the
// surface's embedding after it is added once a frame has built it.
#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <vector>

#include "shared/simulation/simulation.hpp"

namespace altfem {

class EventSchedule {
public:
  EventSchedule(const Scene& scene, Simulation& simulation, std::ostringstream& log);

  /// Applies every event due at `now` (dynamic: the state's time; static: load steps done).
  void apply_due(double now);
  /// The surface of the method an event rebuilt is embedded by the first frame that needs
  /// it, inside a step: its seconds and the vertices it located belong to the event (the
  /// last one, when several came between two frames), added to its record once built.
  /// Called after each frame.
  void add_embedding_report();
  const nlohmann::json& records() const { return records_; }
  /// How many times a cut left a piece of the surface whole (cut_surface's facts).
  int surface_pieces_left_whole() const;

private:
  const std::vector<SceneEvent>& events_;
  Simulation& simulation_;
  std::ostringstream& log_;
  double tolerance_;
  std::size_t next_ = 0;
  nlohmann::json records_ = nlohmann::json::array();
  std::optional<std::size_t> unembedded_;  // the record of the last rebuild whose method has not embedded yet
};

}  // namespace altfem
