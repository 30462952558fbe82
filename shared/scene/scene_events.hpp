#pragma once
// The scene's `events` (docs/scene-schema.md, "events"): their cross-key checks, which
// need the whole scene (the conditions they name, the run's time range), and their
// reading into Scene::events.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "shared/scene/scene.hpp"
#include "shared/scene/scene_schema.hpp"

namespace altfem {

namespace scene_schema {
/// Condition names are unique (events name their target by it).
void check_condition_names(const Validator& validator, const nlohmann::json& conditions);
/// Each event inside the run's time range (dynamic: 0 ≤ time < steps·dt; static: a
/// load-step index 0 … load_steps − 1), naming an existing target, not repeating an
/// event of its kind at its time on its target, and not releasing a condition twice.
void check_events(const Validator& validator, const nlohmann::json& resolved);
/// A cut event's `polygon`: at least 3 corners of [3] finite numbers, planar and convex
/// (blade_polygon_problem).
void check_cut_blade(const Validator& validator, const nlohmann::json& input, nlohmann::json& resolved,
                     const std::string& pointer);
}  // namespace scene_schema

/// The resolved scene's events, sorted by time (scene order among equal times).
std::vector<SceneEvent> events_from_json(const nlohmann::json& resolved);

}  // namespace altfem
