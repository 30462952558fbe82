#pragma once
// fem's grid refined by a scene's `refine` event (issue #34): the marked hexahedra split
// 1→8 and the forest kept 2:1 balanced, hanging nodes constrained to their coarse
// neighbours' interpolation (hexahedral_forest.hpp). Conforming Lagrange spaces need the
// constraints, where dg and harmonic take hanging nodes as they come.
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "shared/mesh/hexahedral_forest.hpp"
#include "shared/scene/scene.hpp"
#include "shared/simulation/prescribed_traction.hpp"

namespace altfem {

struct RefinedGrid {
  HexahedralForest forest;
  ConstrainedHexahedralMesh mesh;  ///< forest_mesh(forest)
};

/// Why a method on a hexahedral grid's forest refuses `refine` (one phrase; empty when it
/// does not): a 1→2 split, or a scene that also cuts (`scene_cuts`).
std::string grid_refine_refusal(const RefineSpec& refine, bool scene_cuts);

/// `forest` with the leaves `refine` marks (mark_cells_to_refine: stresses one per leaf, the
/// error indicator over forest_interior_faces and, with `boundary`, the leaves' faces on
/// the grid's box with its tractions) split 1→8 and balanced; nullopt when none is marked.
/// `boundary` is for a grid whose box is the body (fem); null where the body lies inside
/// the grid (fcm), whose boundary crosses the cut cells and is left out. `facts` gets
/// marked_cells, at_max_level, largest_stress (and largest_indicator), balancing_splits,
/// hanging_nodes and cells (after).
std::optional<RefinedGrid> refine_hexahedral_grid(const HexahedralForest& forest, const RefineSpec& refine,
                                                  const std::vector<Eigen::Matrix3d>& stresses,
                                                  const PrescribedTraction* boundary, nlohmann::json& facts);

}  // namespace altfem
