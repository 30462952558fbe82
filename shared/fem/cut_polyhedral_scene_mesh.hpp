#pragma once
// A polyhedral method's mesh (dg, harmonic) cut by a scene's `cut` event: the polyhedra
// cut (cut_polyhedral_mesh), the pieces below the event's merge fraction of their cell
// merged into a neighbour (Kaufmann et al. 2009 §9.4: negligible pieces make the element
// matrices ill-conditioned), the surface it deforms cut by the same blade (cut_surface),
// the surface loads act on kept, and the converted volume mesh dropped, since its cells no
// longer match.
#include <functional>
#include <nlohmann/json.hpp>
#include <vector>

#include "shared/fem/polyhedral_scene_mesh.hpp"
#include "shared/scene/scene.hpp"

namespace altfem {

/// Per cell of `candidates` (cells of the cut mesh `pieces`, before any merge, geometry
/// computed), whether the method refuses it as an element (harmonic: its MFS fit fails,
/// cut_piece_fits.hpp); a refused cell merges as a piece below the merge fraction does.
using RefusedCells = std::function<std::vector<bool>(const PolyhedralMesh& pieces, const std::vector<int>& candidates)>;

/// `mesh` cut by the blade of `cut`, each piece of a crossed cell below
/// `cut.merge_fraction` of that cell's volume merged into the neighbour across its largest
/// interior face (merge_small_pieces; the union may be non-convex), and so is every other
/// cell `refused` refuses (asked about every cell but those); `facts` gets crossed_cells,
/// joined_cells, separated_faces, duplicated_nodes, snapped_nodes, merged_pieces (both
/// kinds), refused_cells and cells (after). Throws NumericalError as cut_polyhedral_mesh
/// does.
PolyhedralSceneMesh cut_polyhedral_scene_mesh(const PolyhedralSceneMesh& mesh, const SceneEvent& cut,
                                              nlohmann::json& facts, const RefusedCells& refused = {});

}  // namespace altfem
