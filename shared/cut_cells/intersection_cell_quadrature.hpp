#pragma once
// Intersection quadrature (Longva et al. 2020, §4.4–4.5) as the fcm method's source of
// cell rules: any embedded tetrahedral mesh in any background mesh (cell_rules.hpp),
// stiffness rules simplified to at most C(m+3, 3) points, mass rules not (§6), and
// optionally cached on disk (rule_cache.hpp).
#include <filesystem>
#include <memory>
#include <optional>

#include "shared/cut_cells/cell_quadrature.hpp"
#include "shared/cut_cells/cell_rules.hpp"

namespace altfem {

/// What the last stiffness rules cost and how exact they are (for summary.json).
struct IntersectionStatistics {
  Eigen::Index initial_points = 0;  ///< stiffness points of the cut cells before simplification
  Eigen::Index final_points = 0;    ///< … and after
  double max_residual = 0.0;        ///< worst simplification moment residual
  int failed_simplifications = 0;
  double seconds = 0.0;      ///< generation and simplification, stiffness and mass
  int reused_cells = 0;      ///< cells whose stiffness rule came from the previous rules
  int integrated_cells = 0;  ///< cells whose stiffness rule was computed (when rules are remembered)
  /// Tetrahedra whose share of an affine cell's mass reduction came from the previous rules.
  int reused_mass_tetrahedra = 0;
};

/// background: the FCM mesh (hexahedra with planar faces, or tetrahedra); embedded: a
/// Tet4 mesh of the object. `method` and `tolerance` as in SimplificationOptions
/// (method nullopt: stiffness rules are not simplified, §6.3's comparison). With a
/// non-empty cache_directory the rules are read from / written to it. The source keeps
/// copies of both meshes; when `statistics` is given, each call records into it.
/// A non-empty `cell_tetrahedra` (one list per background cell) names the embedded
/// tetrahedra each cell clips: the pieces of a PieceMesh (topology-aware cells), and a
/// non-empty `filled_cells` which of them the material fills (PieceMesh::filled: the
/// standard rule without clipping, CellRuleReuse::filled). Without a
/// cache directory, the rules of a cell found in `previous_rules` are taken from there
/// (a rebuild after an event: only the cells it changed are integrated again), and every
/// cell's rules go into `remembered_rules` (both optional).
CellQuadratureSource intersection_cell_quadrature(
    const VolumeMesh& background, const VolumeMesh& embedded,
    std::optional<SimplificationMethod> method = SimplificationOptions{}.method,
    double tolerance = SimplificationOptions{}.tolerance, const std::filesystem::path& cache_directory = {},
    std::shared_ptr<IntersectionStatistics> statistics = nullptr, std::vector<std::vector<int>> cell_tetrahedra = {},
    std::vector<char> filled_cells = {}, std::shared_ptr<const CellRuleMemory> previous_rules = nullptr,
    std::shared_ptr<CellRuleMemory> remembered_rules = nullptr);

}  // namespace altfem
