// The `dg` block of docs/scene-schema.md, as data; keep the two in step.
#include "dg/dg_scene_block.hpp"

#include <algorithm>

#include "shared/scene/scene_slicing.hpp"

namespace altfem::dg {

namespace {

using nlohmann::json;
using scene_schema::Validator;
using scene_schema::ValueType;

// The keys the `dg` block shares with the `fem` block: the volume mesh that is
// converted into polyhedra ("mesh" first: it alone also names the slicing).
constexpr std::array<std::string_view, 4> mesh_keys{"mesh", "element", "resolution", "max_cell_size"};

template <std::size_t n>
int index_of(const std::array<std::string_view, n>& names, const std::string& name) {
  return static_cast<int>(std::find(names.begin(), names.end(), name) - names.begin());
}

// The defaults that depend on the geometry and on the penalty convention.
// The mesh: hexahedral slicing of a surface or a shape that is not a box (Kaufmann et
// al. 2009, §9.2), unless the block names the converted mesh's keys (element, resolution,
// max_cell_size); a box's grid and a volume mesh file are converted, as fem would mesh them.
void complete_dg_mesh(const Validator& validator, const json& scene, json& dg, const std::string& pointer) {
  const json& geometry = scene["geometry"];
  const bool is_box = geometry.contains("shape") && geometry["shape"].contains("box");
  const bool names_converted_mesh =
      std::any_of(mesh_keys.begin() + 1, mesh_keys.end(), [&](std::string_view key) { return dg.contains(key); });
  if (!dg.contains("mesh"))
    dg["mesh"] = geometry.contains("mesh") ? "file"
                 : is_box                  ? "grid"
                 : names_converted_mesh    ? "tetrahedralize"
                                           : "slice";
  complete_slice_key(validator, dg, pointer);
  if (dg["mesh"] == "slice" &&
      dg.value("embedding", "mls") == "stitched")  // it interpolates with the converted mesh's basis
    validator.fail(pointer + "/embedding",
                   "'stitched' needs a converted mesh (grid, tetrahedralize or file), not mesh "
                   "'slice'; use 'mls' or 'element'");
  if (dg["mesh"] == "slice") {
    for (std::string_view key : mesh_keys)
      if (key != "mesh" && dg.contains(key))
        validator.fail(pointer + "/" + std::string(key),
                       "only with a converted mesh (grid, tetrahedralize or file), not with mesh 'slice'");
    return;
  }
  // Straight-sided cells: the conversion keeps corner nodes only, so the linear element
  // of the mesh kind is the default (a mesh file's own element otherwise).
  if (!dg.contains("element") && dg["mesh"] != "file") dg["element"] = dg["mesh"] == "grid" ? "hex8" : "tet4";
  // The fem block's rules check and complete the mesh keys (messages name this block).
  json mesh = json::object();
  for (std::string_view key : mesh_keys)
    if (dg.contains(key)) mesh[std::string(key)] = dg[std::string(key)];
  fem_scene_block().complete(validator, scene, mesh, pointer);
  for (std::string_view key : mesh_keys)
    if (mesh.contains(key)) dg[std::string(key)] = mesh[std::string(key)];
}

// The first boundary condition the lifted gradient of a nonlinear material cannot carry
// (dg/lifted_gradients.hpp: conditions on all components only), as "pointer: why"; empty if none.
std::string condition_the_lifting_cannot_carry(const json& scene) {
  if (!scene.contains("boundary_conditions")) return {};
  const json& conditions = scene["boundary_conditions"];
  for (size_t c = 0; c < conditions.size(); ++c)
    if (conditions[c].contains("components") && conditions[c]["components"].size() < 3)
      return "/boundary_conditions/" + std::to_string(c) + "/components prescribes " +
             std::to_string(conditions[c]["components"].size()) + " of 3";
  return {};
}

// Whether a condition moves (its data shift F at every time step with the lifted gradient).
bool has_moving_condition(const json& scene) {
  if (!scene.contains("boundary_conditions")) return false;
  for (const json& condition : scene["boundary_conditions"])
    if (condition.contains("motion") && condition["motion"].value("kind", "fixed") != "fixed") return true;
  return false;
}

// The defaults that depend on the geometry and on the penalty convention.
void complete_dg(const Validator& validator, const json& scene, json& dg, const std::string& pointer) {
  complete_dg_mesh(validator, scene, dg, pointer);

  // Other materials than the linear one take interior penalty through the lifted DG
  // gradient (dg/lifted_gradients.hpp), which lifts conditions on all components only.
  // They default to it when every condition is also `fixed`, else to Babuška–Zlámal as
  // before: a moving scene keeps its cheaper default (the lifted cells couple their
  // neighbours, a denser Hessian) and takes interior penalty on request.
  // With `materials`, every one of them must be linear (an absent model is the default, not linear).
  std::string nonlinear_model;
  for (const json& material : scene.contains("materials") ? scene["materials"] : json::array({scene["material"]}))
    if (nonlinear_model.empty() && !(material.contains("model") && material["model"] == "linear"))
      nonlinear_model = material.contains("model") ? material["model"].get<std::string>() : "the default model";
  const bool linear = nonlinear_model.empty();
  const std::string unliftable = linear ? std::string() : condition_the_lifting_cannot_carry(scene);
  if (!dg.contains("flux"))
    dg["flux"] = linear || (unliftable.empty() && !has_moving_condition(scene)) ? "interior_penalty" : "babuska_zlamal";
  if (!unliftable.empty() && dg["flux"] == "interior_penalty")
    validator.fail(pointer + "/flux", "'interior_penalty' with material model '" + nonlinear_model +
                                          "' needs conditions on all components in this build, but " + unliftable +
                                          " (use 'babuska_zlamal')");

  json& penalty = dg["penalty"];
  if (!penalty.contains("convention")) penalty["convention"] = "mfem";
  const auto convention =
      static_cast<PenaltyConvention>(index_of(penalty_convention_names, penalty["convention"].get<std::string>()));
  const int degree = dg["degree"].get<int>();
  if (!penalty.contains("value"))
    penalty["value"] = convention == PenaltyConvention::kaufmann ? 20.0
                       : convention == PenaltyConvention::mfem   ? double((degree + 1) * (degree + 1))
                                                                 : 1.0;
  if (dg["warping"].get<bool>() && !linear)
    validator.fail(pointer + "/warping", "stiffness warping corotates the 'linear' material, got '" + nonlinear_model +
                                             "' (a nonlinear model is already rotation-invariant: use warping false)");
  if (!penalty.contains("double_until_definite")) penalty["double_until_definite"] = true;
  if (dg["conditions"] == "strong" && dg["warping"].get<bool>())
    validator.fail(pointer + "/conditions",
                   "'strong' constrains the cells' coefficients, which stiffness warping "
                   "rotates: not with warping (use 'weak')");
  // Hansbo & Larson's split by default where the penalty is (λ + 2μ)-scaled: without it,
  // k = 1 locks at ν = 0.499 (tests/verify/dg/test_locking.cpp).
  if (!penalty.contains("lame_split")) penalty["lame_split"] = convention != PenaltyConvention::kaufmann;
  if (penalty["lame_split"].get<bool>() && convention == PenaltyConvention::kaufmann)
    validator.fail(
        pointer + "/penalty/lame_split",
        "splits a (λ + 2μ)-scaled penalty, but convention 'kaufmann' scales with E (use 'mfem' or 'dealii')");
}

const scene_schema::ObjectRule penalty_rule{
    {{.key = "convention", .type = ValueType::string, .choices = scene_schema::names(penalty_convention_names)},
     {.key = "value", .type = ValueType::number, .lower = scene_schema::positive},
     {.key = "double_until_definite", .type = ValueType::boolean},
     {.key = "scaling",
      .type = ValueType::string,
      .default_value = "cell_surface",
      .choices = scene_schema::names(penalty_scaling_names)},
     {.key = "lame_split", .type = ValueType::boolean}}};

// The element names the `fem` block accepts (the same volume meshes are converted).
std::vector<std::string_view> fem_element_names() {
  for (const auto& key : fem_scene_block().rule->keys)
    if (key.key == "element") return key.choices;
  return {};
}

// fem's mesh kinds, converted, and `slice`.
std::vector<std::string_view> mesh_names() {
  std::vector<std::string_view> names = scene_schema::names(fem_mesh_names);
  names.push_back("slice");
  return names;
}

// A function-local static: it reads the fem block's rule, which must be initialised first.
const scene_schema::ObjectRule& dg_rule() {
  static const scene_schema::ObjectRule rule{
      {{.key = "degree",
        .type = ValueType::integer,
        .default_value = 2,
        .lower = scene_schema::at_least_one,
        .upper = scene_schema::Bound{3.0, true}},
       {.key = "flux", .type = ValueType::string, .choices = scene_schema::names(flux_names)},
       {.key = "warping", .type = ValueType::boolean, .default_value = false},
       {.key = "conditions",
        .type = ValueType::string,
        .default_value = "weak",
        .choices = scene_schema::names(condition_imposition_names)},
       {.key = "embedding",
        .type = ValueType::string,
        .default_value = "mls",
        .choices = scene_schema::names(embedding_names)},
       {.key = "preconditioner",
        .type = ValueType::string,
        .default_value = "block_jacobi",
        .choices = scene_schema::names(dg_preconditioner_names)},
       {.key = "simplifier",
        .type = ValueType::string,
        .default_value = "caratheodory",
        .choices = scene_schema::names(simplifier_names)},
       {.key = "penalty", .type = ValueType::object, .default_value = json::object(), .object = &penalty_rule},
       {.key = "element", .type = ValueType::string, .choices = fem_element_names()},
       {.key = "mesh", .type = ValueType::string, .choices = mesh_names()},
       {.key = "slice", .type = ValueType::object, .object = &slicing_rule()},
       {.key = "resolution", .type = ValueType::integer3, .lower = scene_schema::at_least_one},
       {.key = "max_cell_size", .type = ValueType::number, .lower = scene_schema::positive}}};
  return rule;
}

}  // namespace

const MethodSceneBlock& dg_scene_block() {
  static const MethodSceneBlock block{"dg", &dg_rule(), complete_dg};
  return block;
}

DgSpec dg_spec(const Scene& scene) {
  const json dg = resolve_method_block(scene, dg_scene_block());
  DgSpec spec;
  spec.degree = dg["degree"].get<int>();
  spec.flux = static_cast<Flux>(index_of(flux_names, dg["flux"].get<std::string>()));
  const json& penalty = dg["penalty"];
  spec.convention =
      static_cast<PenaltyConvention>(index_of(penalty_convention_names, penalty["convention"].get<std::string>()));
  spec.penalty_value = penalty["value"].get<double>();
  spec.double_until_definite = penalty["double_until_definite"].get<bool>();
  spec.scaling = static_cast<PenaltyScaling>(index_of(penalty_scaling_names, penalty["scaling"].get<std::string>()));
  spec.lame_split = penalty["lame_split"].get<bool>();
  spec.warping = dg["warping"].get<bool>();
  spec.strong_conditions = dg["conditions"] == "strong";
  spec.embedding = static_cast<Embedding>(index_of(embedding_names, dg["embedding"].get<std::string>()));
  spec.preconditioner =
      static_cast<DgPreconditioner>(index_of(dg_preconditioner_names, dg["preconditioner"].get<std::string>()));
  spec.rule_simplification = simplifier_from_name(dg["simplifier"].get<std::string>());
  if (dg["mesh"] == "slice") {
    spec.mesh.slicing = slicing_options_from_block(dg["slice"]);
    return spec;
  }
  FemSpec& convert = spec.mesh.convert;
  convert.pointer = "/discretization/dg";
  convert.element = *element_type_from_name(dg["element"].get<std::string>());
  convert.mesh = static_cast<FemMeshKind>(index_of(fem_mesh_names, dg["mesh"].get<std::string>()));
  if (dg.contains("resolution"))
    convert.resolution = {dg["resolution"][0].get<int>(), dg["resolution"][1].get<int>(),
                          dg["resolution"][2].get<int>()};
  if (dg.contains("max_cell_size")) convert.max_cell_size = dg["max_cell_size"].get<double>();
  return spec;
}

FacePenalty face_penalty(const DgSpec& spec, double youngs_modulus, double lambda, double mu) {
  const double k = spec.degree, stiffness = lambda + 2 * mu;
  // Hansbo & Larson 2002: of κ(λ + 2μ), the 2μ part on the whole jump, λ on its normal part.
  const double tangential_fraction = spec.lame_split ? 2 * mu / stiffness : 1.0;
  switch (spec.convention) {
    case PenaltyConvention::kaufmann: return {spec.penalty_value * youngs_modulus, 1.0, 1.0};
    case PenaltyConvention::mfem: return {spec.penalty_value * stiffness / 2, 2.0, tangential_fraction};
    case PenaltyConvention::dealii: return {spec.penalty_value * k * (k + 1) * stiffness / 2, 2.0, tangential_fraction};
  }
  return {spec.penalty_value * youngs_modulus, 1.0, 1.0};
}

}  // namespace altfem::dg
