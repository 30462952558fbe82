// The `slice` object of docs/scene-schema.md ("Slicing"), as data; keep the two in step.
#include "shared/scene/scene_slicing.hpp"

#include "shared/mesh/boundary_surface.hpp"

namespace altfem {

namespace {

using nlohmann::json;
using scene_schema::Validator;
using scene_schema::ValueType;

// Cells along the longest side when neither resolution nor cell_size is given: the bunny
// then has ~700 cells, a few seconds of set-up for dg k = 2 and harmonic on 2 cores.
constexpr int default_resolution = 12;

// resolution and cell_size say the same thing: one of them, resolution by default.
void check_slicing(const Validator& validator, const json&, json& resolved, const std::string& pointer) {
  if (resolved.contains("resolution") && resolved.contains("cell_size"))
    validator.fail(pointer, "give resolution or cell_size, not both");
  if (!resolved.contains("cell_size") && !resolved.contains("resolution")) resolved["resolution"] = default_resolution;
}

}  // namespace

const scene_schema::ObjectRule& slicing_rule() {
  static const scene_schema::ObjectRule rule{
      {{.key = "resolution", .type = ValueType::integer, .lower = scene_schema::at_least_one},
       {.key = "cell_size", .type = ValueType::number, .lower = scene_schema::positive},
       {.key = "margin_cells",
        .type = ValueType::number,
        .default_value = SlicingOptions{}.margin_cells,
        .lower = scene_schema::non_negative},
       {.key = "sliver_fraction",
        .type = ValueType::number,
        .default_value = SlicingOptions{}.sliver_fraction,
        .lower = scene_schema::non_negative,
        .upper = scene_schema::Bound{1.0, false}},
       {.key = "octree_levels",
        .type = ValueType::integer,
        .default_value = SlicingOptions{}.octree_levels,
        .lower = scene_schema::non_negative,
        .upper = scene_schema::Bound{10.0, true}}},
      {},
      {},
      {},
      false,
      check_slicing};
  return rule;
}

void complete_slice_key(const Validator& validator, json& block, const std::string& pointer) {
  if (block["mesh"] == "slice")
    block["slice"] = validator.resolve(block.value("slice", json::object()), slicing_rule(), pointer + "/slice");
  else if (block.contains("slice"))
    validator.fail(pointer + "/slice", "only with mesh 'slice', got mesh '" + block["mesh"].get<std::string>() + "'");
}

SlicingOptions slicing_options_from_block(const json& slice) {
  SlicingOptions options;
  if (slice.contains("resolution")) options.resolution = slice["resolution"].get<int>();
  if (slice.contains("cell_size")) options.cell_size = slice["cell_size"].get<double>();
  options.margin_cells = slice["margin_cells"].get<double>();
  options.sliver_fraction = slice["sliver_fraction"].get<double>();
  options.octree_levels = slice["octree_levels"].get<int>();
  return options;
}

SlicedMesh slice_scene_geometry(const SceneGeometry& geometry, const SlicingOptions& options) {
  if (const SurfaceMesh* surface = geometry.common_surface()) return slice_into_polyhedra(*surface, options);
  return slice_into_polyhedra(boundary_surface(*geometry.mesh).surface, options);
}

json slicing_facts(const SlicedMesh& sliced) {
  return {{"grid", {sliced.grid_cells(0), sliced.grid_cells(1), sliced.grid_cells(2)}},
          {"cell_size", sliced.cell_size},
          {"hexahedra", sliced.hexahedra},
          {"cut_pieces", sliced.cut_pieces},
          {"grid_cells_split_by_topology", sliced.split_grid_cells},
          {"merged_slivers", sliced.merged_slivers},
          {"octree_coarse_cells", sliced.coarse_cells},
          {"grid_shift_cells", sliced.grid_shift_cells}};
}

}  // namespace altfem
