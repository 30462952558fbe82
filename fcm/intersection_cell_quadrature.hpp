#pragma once
// Intersection quadrature (Longva et al. 2020, §4.4–4.5) as the fcm method's source of
// cell rules: any embedded tetrahedral mesh in any background mesh (cell_rules.hpp),
// stiffness rules simplified to at most C(m+3, 3) points, mass rules not (§6), and
// optionally cached on disk (rule_cache.hpp).
#include <filesystem>

#include "fcm/cell_quadrature.hpp"
#include "fcm/cell_rules.hpp"

namespace altfem::fcm {

/// background: the FCM mesh (hexahedra with planar faces, or tetrahedra); embedded: a
/// Tet4 mesh of the object. `method` and `tolerance` as in SimplificationOptions. With a
/// non-empty cache_directory the rules are read from / written to it. The source keeps
/// copies of both meshes.
CellQuadratureSource intersection_cell_quadrature(const VolumeMesh& background, const VolumeMesh& embedded,
                                                  SimplificationMethod method = SimplificationOptions{}.method,
                                                  double tolerance = SimplificationOptions{}.tolerance,
                                                  const std::filesystem::path& cache_directory = {});

}  // namespace altfem::fcm
