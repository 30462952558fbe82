// The `harmonic` block of docs/scene-schema.md, as data; keep the two in step.
#include "polyhedral/harmonic_scene_block.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "shared/scene/scene_slicing.hpp"

namespace altfem::harmonic {

namespace {

using nlohmann::json;
using scene_schema::KeyRule;
using scene_schema::Validator;
using scene_schema::ValueType;

template <typename Enum, std::size_t n>
Enum enum_from_name(const std::array<std::string_view, n>& names, const std::string& name) {
  return static_cast<Enum>(std::find(names.begin(), names.end(), name) - names.begin());
}

// The MFS cells' rule: `simplifier` belongs to `cone`, `subdivision_levels` to
// `subdivision`, `monte_carlo_points` to `monte_carlo`; each defaults with its rule and is
// refused with another. options[k] belongs to HarmonicRuleKind k.
void complete_rule(const Validator& validator, json& harmonic, const std::string& pointer) {
  const HarmonicQuadrature defaults;
  const std::array<std::pair<std::string_view, json>, 3> options{
      {{"simplifier", std::string(defaults.simplifier ? simplification_method_name(*defaults.simplifier) : "none")},
       {"subdivision_levels", defaults.subdivision_levels},
       {"monte_carlo_points", defaults.monte_carlo_points}}};
  const auto kind = static_cast<std::size_t>(enum_from_name<HarmonicRuleKind>(harmonic_rule_names, harmonic["rule"]));
  for (std::size_t k = 0; k < options.size(); ++k) {
    const std::string key(options[k].first);
    if (k == kind) {
      if (!harmonic.contains(key)) harmonic[key] = options[k].second;
    } else if (harmonic.contains(key)) {
      validator.fail(pointer + "/" + key, "only with rule '" + std::string(harmonic_rule_names[k]) + "', got rule '" +
                                              harmonic["rule"].get<std::string>() + "'");
    }
  }
}

// The volume mesh to convert (mesh `convert`, the default) is described exactly as a fem
// block (its rules, its geometry-dependent defaults), except that its element defaults to
// the linear one the conversion keeps: hex8 on a box's grid, tet4 otherwise; a mesh file
// keeps its own. Mesh `slice` reads `slice` instead, and no `convert`.
void complete_harmonic(const Validator& validator, const json& scene, json& harmonic, const std::string& pointer) {
  complete_rule(validator, harmonic, pointer);
  complete_slice_key(validator, harmonic, pointer);
  if (harmonic["mesh"] == "slice") {
    if (harmonic.contains("convert"))
      validator.fail(pointer + "/convert", "only with mesh 'convert', got mesh 'slice'");
    return;
  }
  const MethodSceneBlock& fem = fem_scene_block();
  if (!harmonic.contains("convert"))
    harmonic["convert"] = validator.resolve(json::object(), *fem.rule, pointer + "/convert");
  json& convert = harmonic["convert"];
  const json& geometry = scene["geometry"];
  const bool is_box = geometry.contains("shape") && geometry["shape"].contains("box");
  if (!convert.contains("element") && !geometry.contains("mesh")) {
    const bool grid = convert.contains("mesh") ? convert["mesh"] == "grid" : is_box;
    convert["element"] = grid ? "hex8" : "tet4";
  }
  fem.complete(validator, scene, convert, pointer + "/convert");
}

const scene_schema::ObjectRule& harmonic_rule() {
  static const scene_schema::ObjectRule rule{
      {{.key = "mesh",
        .type = ValueType::string,
        .default_value = "convert",
        .choices = scene_schema::names(harmonic_mesh_names)},
       {.key = "convert", .type = ValueType::object, .object = fem_scene_block().rule},
       {.key = "slice", .type = ValueType::object, .object = &slicing_rule()},
       {.key = "samples_per_edge",
        .type = ValueType::integer,
        .default_value = MfsOptions{}.edge_samples,
        .lower = scene_schema::at_least_one},
       {.key = "kernel_offset",
        .type = ValueType::number,
        .default_value = MfsOptions{}.offset,
        .lower = scene_schema::positive,
        .upper = scene_schema::Bound{1.0, true}},
       {.key = "quadrature_order", .type = ValueType::integer, .default_value = 2, .lower = scene_schema::at_least_one},
       {.key = "rule",
        .type = ValueType::string,
        .default_value = std::string(harmonic_rule_names[0]),
        .choices = scene_schema::names(harmonic_rule_names)},
       {.key = "simplifier", .type = ValueType::string, .choices = scene_schema::names(simplifier_names)},
       {.key = "subdivision_levels",
        .type = ValueType::integer,
        .lower = scene_schema::non_negative,
        .upper = scene_schema::Bound{6, true}},
       {.key = "monte_carlo_points", .type = ValueType::integer, .lower = scene_schema::at_least_one},
       {.key = "basis",
        .type = ValueType::string,
        .default_value = "auto",
        .choices = scene_schema::names(harmonic_basis_names)},
       {.key = "warping", .type = ValueType::boolean, .default_value = false},
       {.key = "cut_piece_residual",
        .type = ValueType::number,
        .default_value = HarmonicSpec{}.cut_piece_residual,
        .lower = scene_schema::positive},
       {.key = "cache", .type = ValueType::string}}};
  return rule;
}

}  // namespace

const MethodSceneBlock& harmonic_scene_block() {
  static const MethodSceneBlock block{"harmonic", &harmonic_rule(), complete_harmonic};
  return block;
}

HarmonicSpec harmonic_spec(const Scene& scene) {
  const json harmonic = resolve_method_block(scene, harmonic_scene_block());
  HarmonicSpec spec;
  if (harmonic["mesh"] == "slice") {
    spec.mesh.slicing = slicing_options_from_block(harmonic["slice"]);
  } else {
    spec.mesh.convert = fem_spec_from_block(harmonic["convert"]);
    spec.mesh.convert.pointer = "/discretization/harmonic/convert";
  }
  spec.mfs.edge_samples = harmonic["samples_per_edge"].get<int>();
  spec.mfs.offset = harmonic["kernel_offset"].get<double>();
  spec.quadrature_order = harmonic["quadrature_order"].get<int>();
  spec.cut_piece_residual = harmonic["cut_piece_residual"].get<double>();
  spec.basis = enum_from_name<HarmonicBasisKind>(harmonic_basis_names, harmonic["basis"]);
  spec.quadrature.kind = enum_from_name<HarmonicRuleKind>(harmonic_rule_names, harmonic["rule"]);
  if (harmonic.contains("simplifier"))
    spec.quadrature.simplifier = simplifier_from_name(harmonic["simplifier"].get<std::string>());
  if (harmonic.contains("subdivision_levels"))
    spec.quadrature.subdivision_levels = harmonic["subdivision_levels"].get<int>();
  if (harmonic.contains("monte_carlo_points"))
    spec.quadrature.monte_carlo_points = harmonic["monte_carlo_points"].get<int>();
  spec.warping = harmonic["warping"].get<bool>();
  if (harmonic.contains("cache")) {
    // A folder, relative to the scene's folder like the scene's file paths.
    const std::filesystem::path cache = harmonic["cache"].get<std::string>();
    const std::filesystem::path& file = scene.file;
    const std::filesystem::path folder =
        file.has_parent_path() ? std::filesystem::absolute(file).parent_path() : std::filesystem::current_path();
    spec.cache = (cache.is_absolute() ? cache : folder / cache).lexically_normal();
  }
  return spec;
}

}  // namespace altfem::harmonic
