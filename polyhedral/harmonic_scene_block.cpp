// The `harmonic` block of docs/scene-schema.md, as data; keep the two in step.
#include "polyhedral/harmonic_scene_block.hpp"

#include <algorithm>
#include <string>

#include "shared/scene/scene_slicing.hpp"

namespace altfem::harmonic {

namespace {

using nlohmann::json;
using scene_schema::KeyRule;
using scene_schema::ValueType;
using scene_schema::Validator;

// The volume mesh to convert (mesh `convert`, the default) is described exactly as a fem
// block (its rules, its geometry-dependent defaults), except that its element defaults to
// the linear one the conversion keeps: hex8 on a box's grid, tet4 otherwise; a mesh file
// keeps its own. Mesh `slice` reads `slice` instead, and no `convert`.
void complete_harmonic(const Validator& validator, const json& scene, json& harmonic, const std::string& pointer) {
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
      {{.key = "mesh", .type = ValueType::string, .default_value = "convert",
        .choices = scene_schema::names(harmonic_mesh_names)},
       {.key = "convert", .type = ValueType::object, .object = fem_scene_block().rule},
       {.key = "slice", .type = ValueType::object, .object = &slicing_rule()},
       {.key = "samples_per_edge", .type = ValueType::integer, .default_value = MfsOptions{}.edge_samples,
        .lower = scene_schema::at_least_one},
       {.key = "kernel_offset", .type = ValueType::number, .default_value = MfsOptions{}.offset,
        .lower = scene_schema::positive, .upper = scene_schema::Bound{1.0, true}},
       {.key = "quadrature_order", .type = ValueType::integer, .default_value = 2, .lower = scene_schema::at_least_one},
       {.key = "basis", .type = ValueType::string, .default_value = "auto",
        .choices = scene_schema::names(harmonic_basis_names)},
       {.key = "warping", .type = ValueType::boolean, .default_value = false},
       {.key = "cache", .type = ValueType::string}}};
  return rule;
}

template <typename Enum, std::size_t n>
Enum enum_from_name(const std::array<std::string_view, n>& names, const std::string& name) {
  return static_cast<Enum>(std::find(names.begin(), names.end(), name) - names.begin());
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
  spec.basis = enum_from_name<HarmonicBasisKind>(harmonic_basis_names, harmonic["basis"]);
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
