#pragma once
// The 2D harmonic coordinates of a polyhedral mesh's faces, fitted once per face and
// shared by the face's two cells (Martin et al. 2008 §4-5: the element functions
// interpolate the face functions, so neighbours that read the same face function have
// the same boundary data). Fitting each face once instead of once per cell halves the
// face work of interior faces and makes the data bit-identical on both sides.
#include <optional>
#include <vector>

#include "polyhedral/element_harmonic_basis.hpp"
#include "shared/mesh/polyhedral_mesh.hpp"

namespace altfem::harmonic {

/// Per mesh face (#faces entries): its coordinates fitted on its stored loop (column k:
/// node mesh.faces[f][k]) when it bounds one of `cells`, else empty; also empty when the
/// fit throws (a degenerate face), which cell_harmonic_basis then reports. Parallel over
/// faces (OpenMP).
std::vector<std::optional<FaceHarmonicCoordinates>> mesh_face_coordinates(const PolyhedralMesh& mesh,
                                                                          const std::vector<int>& cells,
                                                                          const MfsOptions& options);

/// The MFS basis of mesh cell `cell` (its nodes in cell_nodes order) on the shared face
/// coordinates of mesh_face_coordinates. Throws std::invalid_argument when one of its
/// faces has none.
ElementHarmonicBasis cell_harmonic_basis(const PolyhedralMesh& mesh, int cell,
                                         const std::vector<std::optional<FaceHarmonicCoordinates>>& faces,
                                         const MfsOptions& options);

}  // namespace altfem::harmonic
