#include "shared/scene/scene_events.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "shared/common/error.hpp"
#include "shared/mesh/cut_by_surface.hpp"
#include "shared/mesh/surface_mesh.hpp"
#include "shared/scene/scene_shape.hpp"

namespace altfem {

namespace {

// The index of the condition called `name` among the resolved conditions, or −1.
int condition_named(const nlohmann::json& conditions, const std::string& name) {
  for (std::size_t i = 0; i < conditions.size(); ++i)
    if (conditions[i].contains("name") && conditions[i]["name"].get<std::string>() == name) return static_cast<int>(i);
  return -1;
}

// A blade surface file's triangles (an open surface, or a closed one).
std::shared_ptr<const SurfaceBlade> read_blade_surface(const std::string& path) {
  SurfaceMesh surface = read_surface(path, nullptr, false);
  return std::make_shared<const SurfaceBlade>(SurfaceBlade{std::move(surface.vertices), std::move(surface.triangles)});
}

// A cut event's blade: its plane, its polygon or its surface (already checked by check_cut_blade).
CuttingPlane blade_from_json(const nlohmann::json& cut) {
  CuttingPlane blade;
  if (cut.contains("surface")) {
    blade.surface = read_blade_surface(cut["surface"].get<std::string>());
  } else if (cut.contains("plane")) {
    blade.point = vector3_from_json(cut["plane"]["point"]);
    blade.normal = vector3_from_json(cut["plane"]["normal"]);
  } else {
    std::vector<Eigen::Vector3d> corners;
    for (const nlohmann::json& corner : cut["polygon"]) corners.push_back(vector3_from_json(corner));
    blade = polygon_blade(std::move(corners));
  }
  if (cut.contains("piece_at")) blade.piece_at = vector3_from_json(cut["piece_at"]);
  return blade;
}

// A swept blade as the cuts it makes: at the event's time the polygon, then at n more
// times up to sweep.to_time what it has swept so far (n: sweep.substeps, or one per time
// step — per load step for a static scene — it moves through).
void append_sweep(const nlohmann::json& event, const nlohmann::json& time, const SceneEvent& first,
                  std::vector<SceneEvent>& events) {
  const nlohmann::json& sweep = event["cut"]["sweep"];
  const double start = first.time, end = sweep["to_time"].get<double>();
  const double step = time["static"].get<bool>() ? 1.0 : time["dt"].get<double>();
  const int cuts = sweep.contains("substeps") ? sweep["substeps"].get<int>()
                                              : std::max(1, static_cast<int>(std::lround((end - start) / step)));
  const Eigen::Vector3d translation = vector3_from_json(sweep["translation"]);
  const CuttingPlane blade = blade_from_json(event["cut"]);
  for (int cut = 0; cut <= cuts; ++cut) {
    SceneEvent result = first;
    const double fraction = static_cast<double>(cut) / cuts;
    result.kind = EventKind::cut;
    result.time = cut == cuts ? end : start + fraction * (end - start);
    result.blade = cut == 0 ? blade : swept_blade(blade, fraction * translation);
    result.blade.sweep = first.pointer;
    events.push_back(std::move(result));
  }
}

// A refine event as the refinements it makes: one at its time, and with `every` n one per
// n time steps (load steps for a static scene) after it until the run ends; with `cycles` k
// (static scenes) k after the last load step instead, each followed by a re-solve.
void append_refinements(const nlohmann::json& event, const nlohmann::json& time, SceneEvent result,
                        std::vector<SceneEvent>& events) {
  const nlohmann::json& refine = event["refine"];
  result.kind = EventKind::refine;
  result.refine.criterion = refine["criterion"].get<std::string>() == refine_criterion_names[0]
                                ? RefineCriterion::principal_stress
                                : RefineCriterion::error_indicator;
  if (refine.contains("threshold")) result.refine.threshold = refine["threshold"].get<double>();
  if (refine.contains("fraction")) result.refine.fraction = refine["fraction"].get<double>();
  result.refine.split =
      refine["split"].get<std::string>() == refine_split_names[0] ? RefineSplit::eighths : RefineSplit::halves;
  result.refine.max_level = refine["max_level"].get<int>();
  if (refine.contains("region"))
    result.refine.region = region_from_json(refine["region"], result.pointer + "/refine/region");
  const bool is_static = time["static"].get<bool>();
  const double step = is_static ? 1.0 : time["dt"].get<double>();
  // The last time an event can act: after the last load step but one, or before the last step.
  const double last = is_static ? time["load_steps"].get<int>() - 1.0 : step * (time["steps"].get<int>() - 0.5);
  if (refine.contains("cycles")) {
    // After the last load step, one refinement before each re-solve at the full load: times
    // load_steps, load_steps + 1, … count the solves done (run_simulation).
    for (int cycle = 0; cycle < refine["cycles"].get<int>(); ++cycle) {
      result.time = last + 1 + cycle;
      events.push_back(result);
    }
    return;
  }
  const int every = refine.contains("every") ? refine["every"].get<int>() : 0;
  const double first = result.time;
  for (int repeat = 0; repeat == 0 || (every > 0 && first + repeat * every * step <= last); ++repeat) {
    result.time = first + repeat * every * step;
    events.push_back(result);
  }
}

}  // namespace

namespace scene_schema {

using nlohmann::json;

void check_cut_blade(const Validator& validator, const json&, json& resolved, const std::string& pointer) {
  if (resolved.contains("surface")) {
    for (const char* key : {"sweep", "piece_at"})
      if (resolved.contains(key))
        validator.fail(pointer + "/" + key,
                       "a surface blade cuts where its triangles are: give a plane or a polygon "
                       "for a " +
                           std::string(key));
    try {
      read_blade_surface(resolved["surface"].get<std::string>());
    } catch (const InputError& error) {
      validator.fail(pointer + "/surface", "expected a triangulated blade surface: " + std::string(error.what()));
    }
    return;
  }
  if (!resolved.contains("polygon")) {
    if (resolved.contains("sweep"))
      validator.fail(pointer + "/sweep", "a sweep moves a finite blade: give a polygon, not a plane");
    return;
  }
  const json& polygon = resolved["polygon"];
  const std::string where = pointer + "/polygon";
  if (!polygon.is_array() || polygon.size() < 3)
    validator.fail(where, "expected an array of at least 3 corners [x, y, z], got " + describe(polygon));
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const json& corner = polygon[k];
    const bool point =
        corner.is_array() && corner.size() == 3 && std::all_of(corner.begin(), corner.end(), [](const json& value) {
          return value.is_number() && std::isfinite(value.get<double>());
        });
    if (!point)
      validator.fail(where + "/" + std::to_string(k), "expected [x, y, z] of finite numbers, got " + describe(corner));
  }
  const CuttingPlane blade = blade_from_json(resolved);
  if (const std::string problem = blade_polygon_problem(blade); !problem.empty())
    validator.fail(where, "expected a planar convex polygon: " + problem);
  if (!resolved.contains("sweep")) return;
  const json& translation = resolved["sweep"]["translation"];
  const Eigen::Vector3d moved = vector3_from_json(translation);
  if (std::abs(moved.dot(blade.normal.normalized())) > 1e-9 * moved.norm())
    validator.fail(pointer + "/sweep/translation",
                   "expected a translation in the blade's plane (a blade moving out of it would cut a surface that is "
                   "not planar), got " +
                       translation.dump());
}

void check_condition_names(const Validator& validator, const json& conditions) {
  // Discretizations record a DOF's conditions as a 64-bit set (shared/solve/dirichlet_dofs.hpp).
  if (conditions.size() > 64)
    validator.fail("/boundary_conditions", "expected at most 64 conditions, got " + std::to_string(conditions.size()));
  std::map<std::string, std::size_t> first_with_name;
  for (std::size_t i = 0; i < conditions.size(); ++i) {
    if (!conditions[i].contains("name")) continue;
    const std::string name = conditions[i]["name"].get<std::string>();
    const auto [found, inserted] = first_with_name.emplace(name, i);
    if (!inserted)
      validator.fail("/boundary_conditions/" + std::to_string(i) + "/name",
                     "'" + name + "' already names /boundary_conditions/" + std::to_string(found->second) +
                         " (events name their target: each name once)");
  }
}

namespace {

std::string known_names(const json& conditions) {
  std::string names;
  for (const json& condition : conditions)
    if (condition.contains("name")) names += (names.empty() ? "'" : ", '") + condition["name"].get<std::string>() + "'";
  return names.empty() ? "none is named: give the condition a \"name\"" : "named: " + names;
}

void check_time_range(const Validator& validator, const json& time, double event_time, const std::string& pointer) {
  if (time["static"].get<bool>()) {
    const int load_steps = time["load_steps"].get<int>();
    if (event_time != std::floor(event_time) || event_time > load_steps - 1)
      validator.fail(pointer, "a static scene's event acts after a load step: expected an integer 0 … " +
                                  std::to_string(load_steps - 1) + " (time.load_steps = " + std::to_string(load_steps) +
                                  "), got " + describe(json(event_time)));
    return;
  }
  const double end = time["dt"].get<double>() * time["steps"].get<int>();
  if (!(event_time < end))
    validator.fail(pointer, "expected a time before the run ends at steps·dt = " + describe(json(end)) + " s, got " +
                                describe(json(event_time)));
}

}  // namespace

void check_events(const Validator& validator, const json& resolved) {
  const json& events = resolved["events"];
  const json& conditions = resolved["boundary_conditions"];
  std::map<int, std::size_t> released_by;  // condition → the event releasing it
  for (std::size_t i = 0; i < events.size(); ++i) {
    const std::string pointer = "/events/" + std::to_string(i);
    check_time_range(validator, resolved["time"], events[i]["time"].get<double>(), pointer + "/time");
    if (events[i].contains("cut") && events[i]["cut"].contains("sweep")) {
      const double to_time = events[i]["cut"]["sweep"]["to_time"].get<double>();
      check_time_range(validator, resolved["time"], to_time, pointer + "/cut/sweep/to_time");
      if (!(to_time > events[i]["time"].get<double>()))
        validator.fail(pointer + "/cut/sweep/to_time", "expected a time after the event's " +
                                                           describe(events[i]["time"]) + ", got " +
                                                           describe(events[i]["cut"]["sweep"]["to_time"]));
    }
    if (events[i].contains("refine") && events[i]["refine"].contains("cycles")) {
      if (!resolved["time"]["static"].get<bool>())
        validator.fail(pointer + "/refine/cycles",
                       "cycles re-solve a static scene after its last load step: this scene is dynamic (use every)");
      if (events[i]["refine"].contains("every"))
        validator.fail(pointer + "/refine", "expected one of 'every' and 'cycles', got both");
    }
    if (!events[i].contains("release")) continue;
    const std::string name = events[i]["release"].get<std::string>();
    const int condition = condition_named(conditions, name);
    if (condition < 0)
      validator.fail(pointer + "/release",
                     "no boundary condition is named '" + name + "' (" + known_names(conditions) + ")");
    const auto [found, inserted] = released_by.emplace(condition, i);
    if (!inserted) {
      const json& other = events[found->second];
      const bool same_time = other["time"] == events[i]["time"];
      validator.fail(pointer, same_time ? "repeats /events/" + std::to_string(found->second) + " (a release of '" +
                                              name + "' at the same time)"
                                        : "releases '" + name + "' again: /events/" + std::to_string(found->second) +
                                              " already released it");
    }
  }
}

}  // namespace scene_schema

std::vector<SceneEvent> events_from_json(const nlohmann::json& resolved) {
  std::vector<SceneEvent> events;
  const nlohmann::json& conditions = resolved["boundary_conditions"];
  for (std::size_t i = 0; i < resolved["events"].size(); ++i) {
    const nlohmann::json& event = resolved["events"][i];
    SceneEvent result;
    result.time = event["time"].get<double>();
    result.pointer = "/events/" + std::to_string(i);
    if (event.contains("cut")) result.merge_fraction = event["cut"]["merge_fraction"].get<double>();
    if (event.contains("cut") && event["cut"].contains("sweep")) {
      append_sweep(event, resolved["time"], result, events);
      continue;
    }
    if (event.contains("refine")) {
      append_refinements(event, resolved["time"], result, events);
      continue;
    }
    if (event.contains("cut")) {
      result.kind = EventKind::cut;
      result.blade = blade_from_json(event["cut"]);
    } else {
      result.kind = EventKind::release;
      result.condition = condition_named(conditions, event["release"].get<std::string>());
    }
    events.push_back(std::move(result));
  }
  std::stable_sort(events.begin(), events.end(),
                   [](const SceneEvent& a, const SceneEvent& b) { return a.time < b.time; });
  return events;
}

bool events_rebuild(const Scene& scene) {
  return std::any_of(scene.events.begin(), scene.events.end(),
                     [](const SceneEvent& event) { return event.kind != EventKind::release; });
}

}  // namespace altfem
