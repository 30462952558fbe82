#pragma once
// A polyhedral method's mesh (dg, harmonic) refined by a scene's `refine` event: the cells
// whose stress passes the threshold split 1→8 or 1→2 (Kaufmann et al. 2009 §9.3, Martin et
// al. 2008 §8; split_polyhedral_cells), without balancing their neighbours, the surface
// loads act on rebuilt from the split boundary faces, and the converted volume mesh
// dropped, since its cells no longer match.
#include <Eigen/Core>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "shared/assembly/tabulated_elements.hpp"
#include "shared/fem/polyhedral_scene_mesh.hpp"
#include "shared/scene/scene.hpp"
#include "shared/simulation/prescribed_traction.hpp"
#include "shared/simulation/scene_materials.hpp"

namespace altfem {

/// `mesh` with the cells `refine` marks split: a cell whose stress (stresses, one per cell)
/// has a largest absolute principal value above the threshold (or, by the criterion
/// error_indicator, a traction_jump_indicator above it, its boundary faces' tractions
/// from `boundary`), split fewer than max_level
/// times, its centroid in the region and convex (a merged piece is not split). 1→8 splits
/// by the three coordinate planes through the centroid — through the bounding box's centre
/// where the two agree to round-off, so that neighbouring boxes share their mid-planes bit
/// for bit — 1→2 by the plane through the centroid normal to the principal direction.
/// nullopt when no cell is marked. `facts` gets marked_cells, at_max_level,
/// not_convex, largest_stress (and largest_indicator), new_nodes, hanging_nodes
/// and cells (after).
std::optional<PolyhedralSceneMesh> refine_polyhedral_scene_mesh(const PolyhedralSceneMesh& mesh,
                                                                const RefineSpec& refine,
                                                                const std::vector<Eigen::Matrix3d>& stresses,
                                                                const PrescribedTraction& boundary,
                                                                nlohmann::json& facts);

/// A polyhedral method's refinement (MethodInstance::refine_mesh): `mesh` refined as
/// above by the stresses of the displacement u (#dofs) in `elements` (its tabulation, one
/// element per cell, each with its material id into materials.pointers()).
std::optional<PolyhedralSceneMesh> refine_polyhedral_scene_mesh_by_stress(
    const PolyhedralSceneMesh& mesh, const SceneEvent& refine, const TabulatedElements& elements,
    const SceneMaterials& materials, const Eigen::VectorXd& u, const PrescribedTraction& boundary,
    nlohmann::json& facts);

}  // namespace altfem
