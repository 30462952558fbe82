#pragma once
// Hexahedral slicing of a scene's geometry (Kaufmann et al. 2009, §9.2–9.4; Martin et al.
// 2008, §7) as the scene asks for it: the `slice` object of the polyhedral methods' blocks
// (docs/scene-schema.md, "Slicing"), its resolution into SlicingOptions, the slicing of
// whatever geometry the scene names, and the facts summary.json and `altfem mesh` report.
// One place for `altfem mesh --source slice`, `dg` and `harmonic`.
#include <nlohmann/json.hpp>

#include "shared/mesh/slice_into_polyhedra.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/scene/scene_schema.hpp"

namespace altfem {

/// The rule of a `slice` object: `resolution` (cells along the geometry's longest side,
/// default 12) or `cell_size` (not both), `margin_cells`, `sliver_fraction`, `octree_levels`,
/// with the ranges SlicingOptions accepts.
const scene_schema::ObjectRule& slicing_rule();

/// For a method block's `complete` (method_scene_block.hpp): when block["mesh"] is "slice",
/// resolves block["slice"] (absent: {}) by slicing_rule(); with any other mesh a `slice`
/// object is bad input naming pointer/slice.
void complete_slice_key(const scene_schema::Validator& validator, nlohmann::json& block, const std::string& pointer);

/// The options of a `slice` object already resolved by slicing_rule().
SlicingOptions slicing_options_from_block(const nlohmann::json& slice);

/// The geometry sliced by a grid: a surface directly; a shape through its common surface
/// (SceneGeometry::shape_surface, so the cells' boundary faces lie on the surface every
/// method deforms and loads act on); a volume mesh through its boundary.
/// Throws InputError for bad options, NumericalError where the slicer fails.
SlicedMesh slice_scene_geometry(const SceneGeometry& geometry, const SlicingOptions& options);

/// {"grid": [nx, ny, nz], "cell_size", "hexahedra", "cut_pieces",
///  "grid_cells_split_by_topology", "merged_slivers", "octree_coarse_cells", "grid_shift_cells"}.
nlohmann::json slicing_facts(const SlicedMesh& sliced);

}  // namespace altfem
