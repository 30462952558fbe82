// The `fcm` block of docs/scene-schema.md, as data; keep the two in step.
#include "fcm/fcm_scene_block.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <string>

#include "shared/mesh/structured_grid.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem::fcm {

namespace {

using nlohmann::json;
using scene_schema::KeyRule;
using scene_schema::ValueType;

struct CellDefaults {
  int stiffness, mass;
};

// The authors' quadrature strengths (Longva et al. 2020, §6): stiffness rules are
// simplified, mass rules of a higher strength are not. Hex20's mass is 10 because its
// cut-cell rules come from tetrahedral pieces (their 11 applies to the hex rule).
const std::map<std::string, CellDefaults, std::less<>> cell_defaults{
    {"tet4", {1, 2}}, {"tet10", {3, 5}}, {"hex8", {2, 5}}, {"hex20", {4, 10}}, {"hex27", {5, 11}}};

std::vector<std::string_view> cell_names() {
  std::vector<std::string_view> names;
  for (const auto& [name, defaults] : cell_defaults) names.push_back(name);
  return names;
}

constexpr std::array<std::string_view, 2> stabilized_names{"mass_and_stiffness", "mass"};

// The background's size comes from one of `resolution`, `cell_size` or the `background`
// file; a file also names the cell (docs/scene-schema.md, "fcm").
void complete_fcm(const scene_schema::Validator& validator, const json&, json& fcm, const std::string& pointer) {
  if (fcm.contains("resolution") && fcm.contains("cell_size"))
    validator.fail(pointer + "/cell_size", "give resolution or cell_size, not both");
  if (fcm.contains("background")) {
    for (const char* key : {"resolution", "cell_size", "margin"})
      if (fcm.contains(key))
        validator.fail(pointer + "/" + key, "applies only to the generated grid, not to a background mesh file");
    const std::string name(element_name(read_volume_mesh(fcm["background"].get<std::string>()).element_type));
    if (!cell_defaults.contains(name))
      validator.fail(pointer + "/background",
                     "the mesh file's element '" + name + "' is not an fcm cell (tet4, tet10, hex8, hex20, hex27)");
    if (!fcm.contains("cell")) fcm["cell"] = name;
    if (fcm["cell"] != name)
      validator.fail(pointer + "/cell", "must match the background mesh file's element '" + name + "', got '" +
                                            fcm["cell"].get<std::string>() + "'");
  }
  if (!fcm.contains("cell")) fcm["cell"] = "hex20";
  if (!fcm.contains("margin") && !fcm.contains("background")) fcm["margin"] = 0.0;
  const CellDefaults& defaults = cell_defaults.find(fcm["cell"].get<std::string>())->second;
  if (!fcm.contains("quadrature_order")) fcm["quadrature_order"] = defaults.stiffness;
  if (!fcm.contains("mass_quadrature_order")) fcm["mass_quadrature_order"] = defaults.mass;
}

const scene_schema::ObjectRule fcm_rule{
    {{.key = "cell", .type = ValueType::string, .choices = cell_names()},
     {.key = "resolution", .type = ValueType::integer3, .lower = scene_schema::at_least_one},
     {.key = "cell_size", .type = ValueType::number, .lower = scene_schema::positive},
     {.key = "background", .type = ValueType::path, .choices = {".msh", ".mesh"}},
     {.key = "margin",
      .type = ValueType::number,
      .lower = scene_schema::non_negative,
      .upper = scene_schema::Bound{1.0, false}},
     {.key = "embedded_cell_size", .type = ValueType::number, .lower = scene_schema::positive},
     {.key = "quadrature_order", .type = ValueType::integer, .lower = scene_schema::at_least_one},
     {.key = "mass_quadrature_order", .type = ValueType::integer, .lower = scene_schema::at_least_one},
     {.key = "simplifier",
      .type = ValueType::string,
      .default_value = "caratheodory",
      .choices = scene_schema::names(simplifier_names)},
     {.key = "simplification_tolerance",
      .type = ValueType::number,
      .default_value = 1e-12,
      .lower = scene_schema::positive},
     {.key = "discard_fraction",
      .type = ValueType::number,
      .default_value = 0,
      .lower = scene_schema::non_negative,
      .upper = scene_schema::Bound{1.0, false}},
     {.key = "stabilization", .type = ValueType::number, .default_value = 1e-6, .lower = scene_schema::non_negative},
     {.key = "stabilized_matrices",
      .type = ValueType::string,
      .default_value = "mass_and_stiffness",
      .choices = scene_schema::names(stabilized_names)},
     {.key = "schwarz_fraction",
      .type = ValueType::number,
      .default_value = 0.5,
      .lower = scene_schema::non_negative,
      .upper = scene_schema::Bound{1.0, true}},
     {.key = "schwarz_epsilon", .type = ValueType::number, .default_value = 1e-13, .lower = scene_schema::positive},
     {.key = "ghost_penalty", .type = ValueType::number, .default_value = 0.0, .lower = scene_schema::non_negative},
     scene_schema::flag("topology_aware", true)}};

}  // namespace

const MethodSceneBlock& fcm_scene_block() {
  static const MethodSceneBlock block{"fcm", &fcm_rule, complete_fcm};
  return block;
}

FcmSpec fcm_spec(const Scene& scene) {
  const json fcm = resolve_method_block(scene, fcm_scene_block());
  FcmSpec spec;
  spec.cell = *element_type_from_name(fcm["cell"].get<std::string>());
  if (fcm.contains("resolution"))
    spec.resolution = Eigen::Vector3i(fcm["resolution"][0].get<int>(), fcm["resolution"][1].get<int>(),
                                      fcm["resolution"][2].get<int>());
  if (fcm.contains("cell_size")) spec.cell_size = fcm["cell_size"].get<double>();
  if (fcm.contains("background")) spec.background = fcm["background"].get<std::string>();
  else spec.margin = fcm["margin"].get<double>();
  if (fcm.contains("embedded_cell_size")) spec.embedded_cell_size = fcm["embedded_cell_size"].get<double>();
  spec.simplifier = simplifier_from_name(fcm["simplifier"].get<std::string>());
  spec.simplification_tolerance = fcm["simplification_tolerance"].get<double>();
  spec.topology_aware = fcm["topology_aware"].get<bool>();
  FcmOptions& options = spec.options;
  options.quadrature_strength = fcm["quadrature_order"].get<int>();
  options.mass_quadrature_strength = fcm["mass_quadrature_order"].get<int>();
  options.discard_fraction = fcm["discard_fraction"].get<double>();
  options.stabilization = fcm["stabilization"].get<double>();
  options.stabilized = options.stabilization == 0.0           ? StabilizedMatrices::none
                       : fcm["stabilized_matrices"] == "mass" ? StabilizedMatrices::mass
                                                              : StabilizedMatrices::mass_and_stiffness;
  options.schwarz_fraction = fcm["schwarz_fraction"].get<double>();
  options.schwarz_epsilon = fcm["schwarz_epsilon"].get<double>();
  options.ghost_penalty = fcm["ghost_penalty"].get<double>();
  return spec;
}

Eigen::AlignedBox3d background_box(const Eigen::AlignedBox3d& bounds, double margin) {
  const Eigen::Vector3d grow = margin * bounds.sizes();
  return {bounds.min() - grow, bounds.max() + grow};
}

BackgroundMesh background_mesh(const FcmSpec& spec, const Eigen::AlignedBox3d& bounds) {
  if (spec.background) return {read_volume_mesh(*spec.background), std::nullopt};
  Eigen::AlignedBox3d box = background_box(bounds, spec.margin);
  Eigen::Vector3i resolution = spec.resolution.value_or(default_grid_resolution(box.sizes()));
  if (spec.cell_size) {
    // Whole cubic cells from the box's lower corner, the last layer reaching past its top.
    resolution = (box.sizes() / *spec.cell_size).array().ceil().cast<int>().max(1);
    box.max() = box.min() + *spec.cell_size * resolution.cast<double>();
  }
  return {structured_grid(box, resolution, spec.cell), resolution};
}

}  // namespace altfem::fcm
