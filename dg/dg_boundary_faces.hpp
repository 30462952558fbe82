#pragma once
// The faces of a dg mesh with the scene's Dirichlet conditions on them: imposed weakly on
// the whole face (Kaufmann et al. 2009 §4.2), or held strongly (dg/strong_conditions.hpp).
#include <vector>

#include "dg/dg_linear_system.hpp"
#include "shared/mesh/polyhedral_mesh.hpp"
#include "shared/scene/scene.hpp"

namespace altfem::dg {

/// The mesh's faces, a boundary face carrying the first Dirichlet condition whose region
/// holds its centroid. Throws InputError naming a condition whose region holds no
/// boundary face's centroid.
std::vector<DgFace> faces_with_conditions(const PolyhedralMesh& mesh, const Scene& scene);

/// Marks the faces with a condition strong. A cell's strong faces must prescribe the same
/// components (one change of basis per cell); throws InputError naming the first cell whose
/// faces do not. cell_count: the mesh's.
void hold_strongly(const Scene& scene, std::vector<DgFace>& faces, int cell_count);

}  // namespace altfem::dg
