// Every key of docs/scene-schema.md, as data. Keep this file and the document in
// step: a row there is a KeyRule here.
#include "shared/scene/scene_schema.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "shared/scene/scene.hpp"
#include "shared/scene/scene_events.hpp"
#include "shared/scene/scene_shape.hpp"

namespace altfem::scene_schema {

namespace {

using nlohmann::json;

KeyRule required_vector(std::string_view key) { return {.key = key, .type = ValueType::vector3, .required = true}; }
KeyRule required_positive(std::string_view key) {
  return {.key = key, .type = ValueType::number, .required = true, .lower = positive};
}

void check_shape_box(const Validator& validator, const json&, json& resolved, const std::string& pointer) {
  for (int i = 0; i < 3; ++i)
    if (!(resolved["min"][i].get<double>() < resolved["max"][i].get<double>()))
      validator.fail(pointer + "/max/" + std::to_string(i),
                     "must be > min (" + describe(resolved["min"][i]) + "), got " + describe(resolved["max"][i]));
}

void check_region_box(const Validator& validator, const json&, json& resolved, const std::string& pointer) {
  for (int i = 0; i < 3; ++i)
    if (resolved["min"][i].get<double>() > resolved["max"][i].get<double>())
      validator.fail(pointer + "/max/" + std::to_string(i),
                     "must be >= min (" + describe(resolved["min"][i]) + "), got " + describe(resolved["max"][i]));
}

void check_cylinder(const Validator& validator, const json&, json& resolved, const std::string& pointer) {
  if (!(resolved["inner_radius"].get<double>() < resolved["radius"].get<double>()))
    validator.fail(pointer + "/inner_radius", "must be < radius (" + describe(resolved["radius"]) + "), got " +
                                                  describe(resolved["inner_radius"]));
}

void check_translate(const Validator& validator, const json&, json& resolved, const std::string& pointer) {
  if (resolved.contains("displacement") != resolved.contains("duration"))
    validator.fail(pointer + (resolved.contains("duration") ? "/duration" : "/displacement"),
                   "expected 'displacement' and 'duration' together, got only one of them");
}

// `time` is either {"static": true} with optional load steps, or a dynamic run with dt
// and steps.
void check_time(const Validator& validator, const json& input, json& resolved, const std::string& pointer) {
  if (resolved["static"].get<bool>()) {
    for (const auto& [key, value] : input.items())
      if (key != "static" && key != "load_steps")
        validator.fail(pointer + "/" + pointer_token(key), "not allowed with \"static\": true, got " + describe(value));
    resolved = json{{"static", true}, {"load_steps", resolved["load_steps"]}};
    return;
  }
  if (input.contains("load_steps"))
    validator.fail(pointer + "/load_steps", "only for static scenes (a dynamic run steps in time: use dt and steps)");
  resolved.erase("load_steps");
  for (const char* key : {"dt", "steps"})
    if (!resolved.contains(key))
      validator.fail(pointer + "/" + key, std::string("missing required key '") + key + "' (or set \"static\": true)");
}

// `constants`: names the expressions may use, each a finite number (docs/scene-schema.md, "Expressions").
void check_constants(const Validator& validator, const json& constants) {
  if (!constants.is_object())
    validator.fail("/constants", "expected an object of name: number, got " + describe(constants));
  for (const auto& [name, value] : constants.items()) {
    const std::string pointer = "/constants/" + pointer_token(name);
    const bool identifier =
        !name.empty() && (std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_') &&
        std::all_of(name.begin(), name.end(), [](unsigned char c) { return std::isalnum(c) || c == '_'; });
    if (!identifier) validator.fail(pointer, "expected a name of letters, digits and '_' not starting with a digit");
    for (const char* reserved : {"x", "y", "z", "t", "pi", "_pi", "_e"})
      if (name == reserved) validator.fail(pointer, std::string("'") + reserved + "' is reserved; choose another name");
    if (!value.is_number() || !std::isfinite(value.get<double>()))
      validator.fail(pointer, "expected a finite number, got " + describe(value));
  }
}

void check_scene(const Validator& validator, const json&, json& resolved, const std::string&) {
  check_constants(validator, resolved["constants"]);
  check_condition_names(validator, resolved["boundary_conditions"]);
  check_events(validator, resolved);
  if (!resolved.contains("name")) {
    std::string stem = std::filesystem::path(validator.file()).stem().string();
    resolved["name"] = stem.empty() ? "scene" : stem;
  }
  // Each block belongs to a method, which validates it (method_scene_block.hpp); here
  // only the shape every block shares.
  for (const auto& [name, block] : resolved["discretization"].items())
    if (!block.is_object())
      validator.fail("/discretization/" + pointer_token(name),
                     "expected an object (the method's options), got " + describe(block));
}

extern const ObjectRule shape;

// `discretization`: one block per method, each checked by its method.
const ObjectRule method_blocks{{}, {}, {}, {}, true};

const ObjectRule shape_box{{required_vector("min"), required_vector("max")}, {}, {}, {}, {}, check_shape_box};
const ObjectRule shape_sphere{{required_vector("centre"), required_positive("radius")}};
const ObjectRule shape_cylinder{
    {required_vector("base"),
     {.key = "axis", .type = ValueType::vector3, .required = true, .nonzero = true},
     required_positive("height"),
     required_positive("radius"),
     {.key = "inner_radius", .type = ValueType::number, .default_value = 0.0, .lower = non_negative}},
    {},
    {},
    {},
    {},
    check_cylinder};
KeyRule shape_list(std::string_view key) {
  return {.key = key, .type = ValueType::object_array, .object = &shape, .minimum_count = 2};
}
const ObjectRule shape{{{.key = "box", .type = ValueType::object, .object = &shape_box},
                        {.key = "sphere", .type = ValueType::object, .object = &shape_sphere},
                        {.key = "cylinder", .type = ValueType::object, .object = &shape_cylinder},
                        shape_list("union"),
                        shape_list("intersection"),
                        shape_list("difference")},
                       {{"box", "sphere", "cylinder", "union", "intersection", "difference"}}};

const ObjectRule geometry{
    {{.key = "surface", .type = ValueType::path, .choices = {".off", ".obj", ".stl", ".ply"}},
     {.key = "mesh", .type = ValueType::path, .choices = {".msh", ".mesh"}},
     {.key = "shape", .type = ValueType::object, .object = &shape},
     {.key = "scale", .type = ValueType::number, .default_value = 1.0, .lower = positive},
     {.key = "translate", .type = ValueType::vector3, .default_value = json::array({0.0, 0.0, 0.0})}},
    {{"surface", "mesh", "shape"}}};

const ObjectRule region_box{{required_vector("min"), required_vector("max")}, {}, {}, {}, {}, check_region_box};
const ObjectRule region_half_space{
    {required_vector("point"), {.key = "normal", .type = ValueType::vector3, .required = true, .nonzero = true}}};
const ObjectRule region{{{.key = "box", .type = ValueType::object, .object = &region_box},
                         {.key = "half_space", .type = ValueType::object, .object = &region_half_space},
                         {.key = "sphere", .type = ValueType::object, .object = &shape_sphere}},
                        {{"box", "half_space", "sphere"}}};

// The keys of one material; `materials` entries add an optional region.
std::vector<KeyRule> material_keys() {
  return {{.key = "model",
           .type = ValueType::string,
           .default_value = "stable_neo_hookean",
           .choices = names(material_model_names)},
          required_positive("youngs_modulus"),
          {.key = "poisson_ratio",
           .type = ValueType::number,
           .required = true,
           .lower = Bound{-1.0, false},
           .upper = Bound{0.5, false}},
          {.key = "density", .type = ValueType::number, .default_value = 1000.0, .lower = positive}};
}
const ObjectRule material{material_keys()};
std::vector<KeyRule> material_with_region_keys() {
  std::vector<KeyRule> keys = material_keys();
  keys.push_back({.key = "region", .type = ValueType::object, .object = &region});
  return keys;
}
const ObjectRule material_with_region{material_with_region_keys()};

const ObjectRule motion_fixed{{}};
const ObjectRule motion_translate{{{.key = "velocity", .type = ValueType::vector3},
                                   {.key = "displacement", .type = ValueType::vector3},
                                   {.key = "duration", .type = ValueType::number, .lower = positive}},
                                  {{"velocity", "displacement"}},
                                  {},
                                  {},
                                  {},
                                  check_translate};
const ObjectRule motion_rotate{{{.key = "axis", .type = ValueType::vector3, .required = true, .nonzero = true},
                                required_vector("centre"),
                                {.key = "angular_velocity", .type = ValueType::number, .required = true}}};
KeyRule required_expression(std::string_view key) {
  return {.key = key, .type = ValueType::expression3, .required = true};
}
const ObjectRule motion_field{{required_expression("displacement")}};
const ObjectRule motion{
    {},
    {},
    "kind",
    {{"fixed", &motion_fixed}, {"translate", &motion_translate}, {"rotate", &motion_rotate}, {"field", &motion_field}}};

const ObjectRule dirichlet{
    {{.key = "type", .type = ValueType::string, .required = true, .choices = {"dirichlet"}},
     {.key = "region", .type = ValueType::object, .required = true, .object = &region},
     {.key = "motion", .type = ValueType::object, .default_value = json{{"kind", "fixed"}}, .object = &motion},
     {.key = "components", .type = ValueType::components, .default_value = json::array({"x", "y", "z"})},
     {.key = "name", .type = ValueType::string}}};

// `loads.traction` entries: a region and exactly one of a traction vector or a pressure.
const ObjectRule traction{{{.key = "region", .type = ValueType::object, .required = true, .object = &region},
                           {.key = "traction", .type = ValueType::expression3},
                           {.key = "pressure", .type = ValueType::number},
                           {.key = "ramp", .type = ValueType::number, .default_value = 0.0, .lower = non_negative}},
                          {{"traction", "pressure"}}};

const ObjectRule loads{
    {{.key = "gravity", .type = ValueType::vector3, .default_value = json::array({0.0, 0.0, 0.0})},
     {.key = "traction", .type = ValueType::object_array, .default_value = json::array(), .object = &traction},
     {.key = "body_force", .type = ValueType::expression3}}};

const ObjectRule initial_conditions{
    {{.key = "velocity", .type = ValueType::vector3, .default_value = json::array({0.0, 0.0, 0.0})},
     {.key = "angular_velocity", .type = ValueType::vector3, .default_value = json::array({0.0, 0.0, 0.0})},
     {.key = "centre",
      .type = ValueType::vector3_or_string,
      .default_value = "centre_of_mass",
      .choices = {"centre_of_mass"}}}};

const ObjectRule rayleigh_damping{
    {{.key = "mass", .type = ValueType::number, .default_value = 0.0, .lower = non_negative},
     {.key = "stiffness", .type = ValueType::number, .default_value = 0.0, .lower = non_negative}}};

const ObjectRule time{{flag("static", false),
                       {.key = "dt", .type = ValueType::number, .lower = positive},
                       {.key = "steps", .type = ValueType::integer, .lower = at_least_one},
                       {.key = "load_steps", .type = ValueType::integer, .default_value = 1, .lower = at_least_one},
                       {.key = "integrator",
                        .type = ValueType::string,
                        .default_value = "backward_euler",
                        .choices = names(integrator_names)},
                       {.key = "rayleigh_damping",
                        .type = ValueType::object,
                        .default_value = json::object(),
                        .object = &rayleigh_damping}},
                      {},
                      {},
                      {},
                      {},
                      check_time};

const ObjectRule solver{
    {{.key = "nonlinear",
      .type = ValueType::string,
      .default_value = "newton",
      .choices = names(nonlinear_solver_names)},
     {.key = "tolerance", .type = ValueType::number, .default_value = 1e-5, .lower = positive},
     {.key = "max_iterations", .type = ValueType::integer, .default_value = 50, .lower = at_least_one},
     flag("line_search", true),
     flag("project_spd", false),
     {.key = "linear",
      .type = ValueType::string,
      .default_value = "cholmod",
      .choices = names(linear_solver_kind_names)},
     {.key = "preconditioner",
      .type = ValueType::string,
      .default_value = "jacobi",
      .choices = names(preconditioner_names)},
     {.key = "linear_tolerance", .type = ValueType::number, .default_value = 1e-10, .lower = positive},
     {.key = "linear_max_iterations", .type = ValueType::integer, .default_value = 10000, .lower = at_least_one},
     {.key = "petsc_options", .type = ValueType::string, .default_value = "-ksp_type cg -pc_type gamg"},
     flag("rigid_body_modes", true),
     flag("method_smoother", true),
     flag("p_multigrid", true),
     {.key = "cutbacks",
      .type = ValueType::integer,
      .default_value = 10,
      .lower = non_negative,
      .upper = Bound{30.0, true}}}};

const ObjectRule output{{{.key = "every", .type = ValueType::integer, .default_value = 1, .lower = at_least_one},
                         flag("surface", true),
                         flag("volume", true)}};

// The `compare` block (docs/scene-schema.md, "compare"): only its shape is checked
// here; method names are checked by `altfem compare` against the build's registry.
void check_compare_methods(const Validator& validator, const json& methods, const std::string& pointer) {
  if (!methods.is_array() || methods.empty())
    validator.fail(pointer, "expected a non-empty array of method names, got " + describe(methods));
  for (std::size_t i = 0; i < methods.size(); ++i)
    if (!methods[i].is_string() || methods[i].get<std::string>().empty())
      validator.fail(pointer + "/" + std::to_string(i), "expected a method name, got " + describe(methods[i]));
}

void check_compare(const Validator& validator, const json&, json& resolved, const std::string& pointer) {
  if (resolved.contains("methods")) check_compare_methods(validator, resolved["methods"], pointer + "/methods");
  if (!resolved.contains("sweeps")) return;
  const json& sweeps = resolved["sweeps"];
  if (!sweeps.is_object() && !(sweeps.is_array() && !sweeps.empty()))
    validator.fail(
        pointer + "/sweeps",
        "expected an object of JSON pointer: [values], or a non-empty array of them, got " + describe(sweeps));
  const json groups = sweeps.is_array() ? sweeps : json::array({sweeps});
  for (std::size_t group = 0; group < groups.size(); ++group) {
    const std::string at = pointer + "/sweeps" + (sweeps.is_array() ? "/" + std::to_string(group) : "");
    if (!groups[group].is_object())
      validator.fail(at, "expected an object of JSON pointer: [values], got " + describe(groups[group]));
    for (const auto& [key, values] : groups[group].items())
      if (!values.is_array() || values.empty())
        validator.fail(at + "/" + pointer_token(key), "expected a non-empty array of values, got " + describe(values));
  }
}

void check_compare_reference(const Validator& validator, const json&, json& resolved, const std::string& pointer) {
  if (!resolved["set"].is_object())
    validator.fail(pointer + "/set", "expected an object of JSON pointer: value, got " + describe(resolved["set"]));
}

const ObjectRule compare_reference{{{.key = "method", .type = ValueType::string, .required = true},
                                    {.key = "set", .type = ValueType::any, .default_value = json::object()}},
                                   {},
                                   {},
                                   {},
                                   {},
                                   check_compare_reference};

const ObjectRule compare{{{.key = "methods", .type = ValueType::any},
                          {.key = "sweeps", .type = ValueType::any},
                          {.key = "reference", .type = ValueType::object, .object = &compare_reference},
                          {.key = "error", .type = ValueType::number, .lower = positive}},
                         {},
                         {},
                         {},
                         {},
                         check_compare};

// `events` entries: a time and exactly one kind (cross-checked by check_events).
const ObjectRule cut_sweep{{{.key = "to_time", .type = ValueType::number, .required = true, .lower = positive},
                            {.key = "translation", .type = ValueType::vector3, .required = true, .nonzero = true},
                            {.key = "substeps", .type = ValueType::integer, .lower = at_least_one}}};
const ObjectRule cut_event{{{.key = "plane", .type = ValueType::object, .object = &region_half_space},
                            {.key = "polygon", .type = ValueType::any},
                            {.key = "surface", .type = ValueType::path, .choices = {".off", ".obj", ".stl", ".ply"}},
                            {.key = "sweep", .type = ValueType::object, .object = &cut_sweep},
                            {.key = "piece_at", .type = ValueType::vector3},
                            {.key = "merge_fraction",
                             .type = ValueType::number,
                             .default_value = 1e-3,
                             .lower = non_negative,
                             .upper = Bound{1.0, false}}},
                           {{"plane", "polygon", "surface"}},
                           {},
                           {},
                           false,
                           check_cut_blade};

const ObjectRule refine_event{
    {{.key = "criterion",
      .type = ValueType::string,
      .default_value = "principal_stress",
      .choices = names(refine_criterion_names)},
     {.key = "threshold", .type = ValueType::number, .lower = non_negative},
     {.key = "fraction", .type = ValueType::number, .lower = Bound{0.0, false}, .upper = Bound{1.0, true}},
     {.key = "split", .type = ValueType::string, .default_value = "1to8", .choices = names(refine_split_names)},
     {.key = "max_level", .type = ValueType::integer, .default_value = 3, .lower = at_least_one},
     {.key = "region", .type = ValueType::object, .object = &region},
     {.key = "every", .type = ValueType::integer, .lower = at_least_one},
     {.key = "cycles", .type = ValueType::integer, .lower = at_least_one}},
    {{"threshold", "fraction"}}};

const ObjectRule event{{{.key = "time", .type = ValueType::number, .required = true, .lower = non_negative},
                        {.key = "release", .type = ValueType::string},
                        {.key = "cut", .type = ValueType::object, .object = &cut_event},
                        {.key = "refine", .type = ValueType::object, .object = &refine_event}},
                       {{"release", "cut", "refine"}}};

const ObjectRule scene{
    {{.key = "name", .type = ValueType::string},
     {.key = "geometry", .type = ValueType::object, .required = true, .object = &geometry},
     {.key = "material", .type = ValueType::object, .object = &material},
     {.key = "materials", .type = ValueType::object_array, .object = &material_with_region, .minimum_count = 1},
     {.key = "boundary_conditions",
      .type = ValueType::object_array,
      .default_value = json::array(),
      .object = &dirichlet},
     {.key = "loads", .type = ValueType::object, .default_value = json::object(), .object = &loads},
     {.key = "initial_conditions",
      .type = ValueType::object,
      .default_value = json::object(),
      .object = &initial_conditions},
     {.key = "time", .type = ValueType::object, .default_value = json{{"static", true}}, .object = &time},
     {.key = "solver", .type = ValueType::object, .default_value = json::object(), .object = &solver},
     {.key = "output", .type = ValueType::object, .default_value = json::object(), .object = &output},
     {.key = "discretization", .type = ValueType::object, .default_value = json::object(), .object = &method_blocks},
     {.key = "compare", .type = ValueType::object, .object = &compare},
     {.key = "constants", .type = ValueType::any, .default_value = json::object()},
     {.key = "exact_displacement", .type = ValueType::expression3},
     {.key = "events", .type = ValueType::object_array, .default_value = json::array(), .object = &event}},
    {{"material", "materials"}},
    {},
    {},
    {},
    check_scene};

}  // namespace

const ObjectRule& scene_rule() { return scene; }

}  // namespace altfem::scene_schema
