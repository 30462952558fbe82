// Scene text → validated, resolved JSON (scene_schema) → the plain structs of scene.hpp.
#include "shared/scene/scene.hpp"

#include <algorithm>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>
#include <vector>

#include "shared/common/error.hpp"
#include "shared/scene/scene_events.hpp"
#include "shared/scene/scene_override.hpp"
#include "shared/scene/scene_schema.hpp"
#include "shared/scene/scene_shape.hpp"

namespace altfem {

namespace {

using nlohmann::json;

template <typename Kind, std::size_t n>
Kind kind_from_name(const std::array<std::string_view, n>& names, const json& value) {
  const auto found = std::find(names.begin(), names.end(), value.get<std::string>());
  return static_cast<Kind>(found - names.begin());  // validated: always found
}

// "line L, column C" of the character at `offset`.
std::string line_and_column(std::string_view text, std::size_t offset) {
  const std::string_view before = text.substr(0, std::min(offset, text.size()));
  const std::size_t line = 1 + std::count(before.begin(), before.end(), '\n');
  const std::size_t line_start = before.rfind('\n');
  const std::size_t column = 1 + before.size() - (line_start == std::string_view::npos ? 0 : line_start + 1);
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// nlohmann reports a byte offset (1-based: the characters read so far, so the
// position is that of the last character read); people want a line and a column.
std::string syntax_message(std::string_view text, const std::string& file, const json::parse_error& error) {
  // Keep nlohmann's explanation, without its own prefix and position.
  std::string detail = error.what();
  if (const auto at = detail.find("column "); at != std::string::npos)
    if (const auto colon = detail.find(": ", at); colon != std::string::npos) detail = detail.substr(colon + 2);
  std::replace_if(
      detail.begin(), detail.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
  return input_message(file, line_and_column(text, error.byte > 0 ? error.byte - 1 : 0),
                       "JSON syntax error: " + detail);
}

// nlohmann refuses numbers beyond double range ("number overflow parsing '1e999'")
// without a position: find the literal in the text to give one.
std::string overflow_message(std::string_view text, const std::string& file, const json::out_of_range& error) {
  const std::string what = error.what();
  const auto start = what.find('\'');
  const auto end = what.rfind('\'');
  if (start == std::string::npos || end <= start + 1) return input_message(file, "", "JSON error: " + what);
  const std::string literal = what.substr(start + 1, end - start - 1);
  const auto offset = text.find(literal);
  return input_message(file, offset == std::string_view::npos ? "" : line_and_column(text, offset),
                       "expected a finite number, got " + literal);
}

// JSON allows repeated keys and nlohmann silently keeps the last one, so a scene
// that sets "dt" twice would run with whichever came second. This parser callback
// tracks the keys of every open object and the JSON pointer to it, and remembers the
// first repeated key.
class DuplicateKeyFinder {
public:
  bool operator()(int /*depth*/, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start: open(false); break;
      case json::parse_event_t::array_start: open(true); break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end: frames_.pop_back(); break;
      case json::parse_event_t::key: {
        Frame& object = frames_.back();
        object.key = parsed.get<std::string>();
        if (!object.keys.insert(object.key).second && duplicate_.empty()) duplicate_ = pointer();
        break;
      }
      case json::parse_event_t::value:
        if (!frames_.empty() && frames_.back().is_array) ++frames_.back().index;
        break;
    }
    return true;
  }
  /// The JSON pointer of the first repeated key, or "" when there is none.
  const std::string& duplicate() const { return duplicate_; }

private:
  struct Frame {
    bool is_array;
    std::set<std::string> keys;
    std::string key;
    int index = -1;
  };
  void open(bool is_array) {
    if (!frames_.empty() && frames_.back().is_array) ++frames_.back().index;
    frames_.push_back({is_array, {}, {}, -1});
  }
  // RFC 6901: '~' and '/' inside a key are written "~0" and "~1".
  static std::string escaped(const std::string& key) {
    std::string out;
    for (char c : key) {
      if (c == '~') out += "~0";
      else if (c == '/') out += "~1";
      else out += c;
    }
    return out;
  }
  std::string pointer() const {
    std::string out;
    for (const Frame& frame : frames_) {
      out += '/';
      out += frame.is_array ? std::to_string(frame.index) : escaped(frame.key);
    }
    return out;
  }

  std::vector<Frame> frames_;
  std::string duplicate_;
};

// The three components of an expression key (validated: strings or numbers).
VectorExpression expression_from_json(const json& value, const ExpressionConstants& constants, const std::string& file,
                                      const std::string& pointer,
                                      ExpressionVariables variables = ExpressionVariables::position_and_time) {
  std::array<std::string, 3> components;
  for (int i = 0; i < 3; ++i) components[i] = value[i].is_string() ? value[i].get<std::string>() : value[i].dump();
  return VectorExpression(components, constants, file, pointer, variables);
}

Motion motion_from_json(const json& value, const ExpressionConstants& constants, const std::string& file,
                        const std::string& pointer) {
  Motion motion;
  motion.kind = kind_from_name<MotionKind>(motion_kind_names, value["kind"]);
  if (value.contains("velocity")) motion.velocity = vector3_from_json(value["velocity"]);
  if (motion.kind == MotionKind::field) {
    motion.field = expression_from_json(value["displacement"], constants, file, pointer + "/displacement");
  } else if (value.contains("displacement")) {
    motion.total_displacement = vector3_from_json(value["displacement"]);
    motion.duration = value["duration"].get<double>();
  }
  if (motion.kind == MotionKind::rotate) {
    motion.axis = vector3_from_json(value["axis"]).normalized();
    motion.centre = vector3_from_json(value["centre"]);
    motion.angular_velocity = value["angular_velocity"].get<double>();
  }
  return motion;
}

GeometrySpec geometry_from_json(const json& value) {
  GeometrySpec geometry;
  if (value.contains("surface")) {
    geometry.kind = GeometryKind::surface;
    geometry.file = value["surface"].get<std::string>();
  } else if (value.contains("mesh")) {
    geometry.kind = GeometryKind::mesh;
    geometry.file = value["mesh"].get<std::string>();
  } else {
    geometry.kind = GeometryKind::shape;
    geometry.shape = shape_from_json(value["shape"]);
  }
  geometry.scale = value["scale"].get<double>();
  geometry.translate = vector3_from_json(value["translate"]);
  return geometry;
}

Scene scene_from_json(json resolved, const std::filesystem::path& file) {
  Scene scene;
  scene.file = file;
  scene.name = resolved["name"].get<std::string>();
  const std::string file_name = file.string();
  const ExpressionConstants constants = resolved["constants"].get<ExpressionConstants>();
  scene.geometry = geometry_from_json(resolved["geometry"]);

  const auto material_from_json = [](const json& material, const std::string& pointer) {
    MaterialSpec spec{material["model"].get<std::string>(),
                      material["youngs_modulus"].get<double>(),
                      material["poisson_ratio"].get<double>(),
                      material["density"].get<double>(),
                      std::nullopt,
                      pointer};
    if (material.contains("region")) spec.region = region_from_json(material["region"], pointer + "/region");
    return spec;
  };
  if (resolved.contains("material")) scene.materials.push_back(material_from_json(resolved["material"], "/material"));
  else
    for (std::size_t i = 0; i < resolved["materials"].size(); ++i)
      scene.materials.push_back(material_from_json(resolved["materials"][i], "/materials/" + std::to_string(i)));
  scene.material = scene.materials.front();

  const json& conditions = resolved["boundary_conditions"];
  for (std::size_t i = 0; i < conditions.size(); ++i) {
    const std::string pointer = "/boundary_conditions/" + std::to_string(i);
    DirichletCondition condition;
    condition.pointer = pointer;
    condition.region = region_from_json(conditions[i]["region"], pointer + "/region");
    condition.motion = motion_from_json(conditions[i]["motion"], constants, file_name, pointer + "/motion");
    condition.components = {false, false, false};
    for (const auto& component : conditions[i]["components"])
      condition.components[component.get<std::string>()[0] - 'x'] = true;
    if (conditions[i].contains("name")) condition.name = conditions[i]["name"].get<std::string>();
    scene.dirichlet.push_back(condition);
  }

  scene.gravity = vector3_from_json(resolved["loads"]["gravity"]);
  const json& tractions = resolved["loads"]["traction"];
  for (std::size_t i = 0; i < tractions.size(); ++i) {
    SurfaceTraction load;
    load.pointer = "/loads/traction/" + std::to_string(i);
    load.region = region_from_json(tractions[i]["region"], load.pointer + "/region");
    if (!tractions[i].contains("traction")) {
      load.pressure = tractions[i]["pressure"].get<double>();
    } else if (const json& traction = tractions[i]["traction"];
               std::all_of(traction.begin(), traction.end(), [](const json& v) { return v.is_number(); })) {
      load.traction = vector3_from_json(traction);
    } else {  // expressions, which may use the surface's normal
      load.traction_field = expression_from_json(traction, constants, file_name, load.pointer + "/traction",
                                                 ExpressionVariables::surface);
    }
    load.ramp = tractions[i]["ramp"].get<double>();
    scene.tractions.push_back(load);
  }
  if (resolved["loads"].contains("body_force"))
    scene.body_force = expression_from_json(resolved["loads"]["body_force"], constants, file_name, "/loads/body_force");
  if (resolved.contains("exact_displacement"))
    scene.exact_displacement =
        expression_from_json(resolved["exact_displacement"], constants, file_name, "/exact_displacement");

  const json& initial = resolved["initial_conditions"];
  scene.initial.velocity = vector3_from_json(initial["velocity"]);
  scene.initial.angular_velocity = vector3_from_json(initial["angular_velocity"]);
  if (initial["centre"].is_array()) scene.initial.centre = vector3_from_json(initial["centre"]);

  const json& time = resolved["time"];
  scene.time.is_static = time["static"].get<bool>();
  if (scene.time.is_static) scene.time.load_steps = time["load_steps"].get<int>();
  if (!scene.time.is_static) {
    scene.time.dt = time["dt"].get<double>();
    scene.time.steps = time["steps"].get<int>();
    scene.time.integrator = kind_from_name<IntegratorKind>(integrator_names, time["integrator"]);
    scene.time.rayleigh_mass = time["rayleigh_damping"]["mass"].get<double>();
    scene.time.rayleigh_stiffness = time["rayleigh_damping"]["stiffness"].get<double>();
  }

  const json& solver = resolved["solver"];
  scene.solver = {kind_from_name<NonlinearSolverKind>(nonlinear_solver_names, solver["nonlinear"]),
                  solver["tolerance"].get<double>(),
                  solver["max_iterations"].get<int>(),
                  solver["line_search"].get<bool>(),
                  solver["project_spd"].get<bool>(),
                  kind_from_name<LinearSolverKind>(linear_solver_kind_names, solver["linear"]),
                  solver["preconditioner"].get<std::string>(),
                  solver["linear_tolerance"].get<double>(),
                  solver["linear_max_iterations"].get<int>(),
                  solver["petsc_options"].get<std::string>(),
                  solver["rigid_body_modes"].get<bool>(),
                  solver["method_smoother"].get<bool>(),
                  solver["p_multigrid"].get<bool>(),
                  solver["cutbacks"].get<int>()};

  const json& output = resolved["output"];
  scene.output = {output["every"].get<int>(), output["surface"].get<bool>(), output["volume"].get<bool>()};
  scene.events = events_from_json(resolved);

  scene.resolved = std::move(resolved);
  return scene;
}

}  // namespace

RegionSelector region_from_json(const json& region, const std::string& pointer) {
  RegionSelector selector;
  selector.pointer = pointer;
  if (region.contains("box")) {
    selector.kind = RegionKind::box;
    selector.box =
        Eigen::AlignedBox3d(vector3_from_json(region["box"]["min"]), vector3_from_json(region["box"]["max"]));
  } else if (region.contains("half_space")) {
    selector.kind = RegionKind::half_space;
    selector.point = vector3_from_json(region["half_space"]["point"]);
    selector.normal = vector3_from_json(region["half_space"]["normal"]).normalized();
  } else {
    selector.kind = RegionKind::sphere;
    selector.centre = vector3_from_json(region["sphere"]["centre"]);
    selector.radius = region["sphere"]["radius"].get<double>();
  }
  return selector;
}

Scene parse_scene(std::string_view text, const std::filesystem::path& file) { return parse_scene(text, file, {}); }

Scene parse_scene(std::string_view text, const std::filesystem::path& file,
                  const std::vector<SceneOverride>& overrides) {
  const std::string name = file.string();
  if (std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isspace(c); }))
    throw InputError(input_message(name, "line 1, column 1", "expected a JSON object, got an empty file"));
  json document;
  DuplicateKeyFinder duplicates;
  try {
    document = json::parse(text.begin(), text.end(), std::ref(duplicates));
  } catch (const json::parse_error& error) {
    throw InputError(syntax_message(text, name, error));
  } catch (const json::out_of_range& error) {
    throw InputError(overflow_message(text, name, error));
  } catch (const json::exception& error) {
    throw InputError(input_message(name, "", std::string("JSON error: ") + error.what()));
  }
  if (!duplicates.duplicate().empty())
    throw InputError(input_message(name, duplicates.duplicate(),
                                   "key repeated in its object (JSON keeps only one; "
                                   "write each key once)"));
  apply_scene_overrides(document, overrides, name);
  const std::filesystem::path folder =
      file.has_parent_path() ? std::filesystem::absolute(file).parent_path() : std::filesystem::current_path();
  const scene_schema::Validator validator(name, folder);
  return scene_from_json(validator.resolve(document, scene_schema::scene_rule(), ""), file);
}

Scene load_scene(const std::filesystem::path& path) { return load_scene(path, {}); }

Scene load_scene(const std::filesystem::path& path, const std::vector<SceneOverride>& overrides) {
  std::ifstream stream(path, std::ios::binary);
  if (!stream || std::filesystem::is_directory(path)) {
    std::error_code error;
    const std::string what = std::filesystem::is_directory(path, error) ? "a folder"
                             : std::filesystem::exists(path, error)     ? "a file that cannot be read"
                                                                        : "no such file";
    throw InputError(input_message(path.string(), "", "expected a readable scene file, got " + what));
  }
  std::ostringstream text;
  text << stream.rdbuf();
  Scene scene = parse_scene(text.str(), path, overrides);
  if (scene.geometry.kind != GeometryKind::shape && !std::filesystem::is_regular_file(scene.geometry.file)) {
    const char* key = scene.geometry.kind == GeometryKind::surface ? "surface" : "mesh";
    throw InputError(input_message(path.string(), std::string("/geometry/") + key,
                                   "expected an existing file, got " + json(scene.geometry.file.string()).dump()));
  }
  return scene;
}

}  // namespace altfem
