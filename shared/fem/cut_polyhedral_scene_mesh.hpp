#pragma once
// A polyhedral method's mesh (dg, harmonic) cut by a scene's `cut` event: the polyhedra
// cut (cut_polyhedral_mesh), the pieces below the event's merge fraction of their cell
// merged into a neighbour (Kaufmann et al. 2009 §9.4: negligible pieces make the element
// matrices ill-conditioned), the surface it deforms cut by the same blade (cut_surface),
// the surface loads act on kept, and the converted volume mesh dropped, since its cells no
// longer match.
#include <nlohmann/json.hpp>

#include "shared/fem/polyhedral_scene_mesh.hpp"
#include "shared/scene/scene.hpp"

namespace altfem {

/// `mesh` cut by the blade of `cut`, each piece of a crossed cell below
/// `cut.merge_fraction` of that cell's volume merged into the neighbour across its largest
/// interior face (merge_small_pieces; the union may be non-convex); `facts` gets
/// crossed_cells, joined_cells, separated_faces, duplicated_nodes, snapped_nodes,
/// merged_pieces and cells (after). Throws NumericalError as cut_polyhedral_mesh does.
PolyhedralSceneMesh cut_polyhedral_scene_mesh(const PolyhedralSceneMesh& mesh, const SceneEvent& cut,
                                              nlohmann::json& facts);

}  // namespace altfem
