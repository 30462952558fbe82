#pragma once
// Quadrature rules for every cell of a background mesh with an embedded tetrahedral
// mesh (Longva et al. 2020, §4.4–4.5): cells outside get no points, cells entirely
// inside the standard reference rule, cut cells the intersection rule simplified to at
// most M = C(m+3, 3) points. Cells are independent: computed in parallel (OpenMP),
// each thread with its own scratch, writing only its own cell's entry.
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include "shared/cut_cells/tetrahedron_reductions.hpp"
#include "shared/fem/lagrange_element_masses.hpp"
#include "shared/geometry/clip_convex.hpp"
#include "shared/mesh/volume_mesh.hpp"
#include "shared/quadrature/quadrature_rule.hpp"
#include "shared/quadrature/simplify_quadrature.hpp"

namespace altfem {

enum class CellKind { outside, inside, cut };

/// Relative difference between a cell's clipped volume and its own under which the
/// material fills the cell: it is inside, with the standard rule.
constexpr double filled_cell_tolerance = 1e-12;

struct CellRuleOptions {
  int order = 4;         ///< m: polynomial degree integrated exactly
  bool simplify = true;  ///< false keeps the intersection rules (§6.3's comparison)
  SimplificationMethod method = SimplificationOptions{}.method;
  double tolerance = SimplificationOptions{}.tolerance;  ///< accepted moment residual
  /// How the clipped pieces of an affine cell are tetrahedralised (other cells: the
  /// centroid's fan). A rule inexact for its integrand depends on its pieces, so it keeps
  /// the centroid's fan; one exact for its integrand (a mass rule of at least twice the
  /// basis' degree), or one simplified (which keeps only its degree-m moments, exact on any
  /// pieces), may take the vertex's, of about half the points.
  PieceFan fan = PieceFan::centroid;
  /// The degree of the integrand where it is a polynomial (the basis' products, for mass
  /// rules): on an affine cell a piece's rule of that strength is already exact, whatever
  /// the fan, so the pieces there take min(order, exact_degree) — the same integrals to
  /// round-off from fewer points (fcm Hex20's default mass strength 10: 46 points a piece
  /// instead of 81). 0: `order` everywhere.
  int exact_degree = 0;
  /// Also reduce each cut cell's rule (CellRule::reduced): for mass rules, which serve
  /// only the masses and are never simplified. An affine cut cell then gets its
  /// reduction alone, summed over its tetrahedra (tetrahedron_reductions.hpp), and no
  /// points: its masses are the reduction times det J.
  bool reduce = false;
};

struct CellRule {
  CellKind kind = CellKind::outside;
  QuadratureRule rule;                 ///< reference coordinates of the cell; ∫ f ≈ Σ w f(ξ)|J(ξ)|
  Eigen::Index initial_points = 0;     ///< before simplification
  double clipped_volume = 0.0;         ///< physical volume of cell ∩ geometry
  double residual = 0.0;               ///< simplification residual (SimplificationResult)
  bool simplification_failed = false;  ///< the original rule was kept
  /// With CellRuleOptions::reduce, a cut cell's rule reduced on its reference element
  /// (an affine cell's `rule` is then empty): a remembered rule (CellRuleMemory) keeps it,
  /// so a rebuild reads the rule's points never.
  std::optional<ReferenceProducts> reduced;
};

struct CellRules {
  std::vector<CellRule> cells;  ///< one per background cell, in mesh order
  Eigen::Index initial_points = 0, final_points = 0;
  int cut_cells = 0, inside_cells = 0, failed_simplifications = 0;
  double max_residual = 0.0;
};

/// Rules computed before: a rebuild after an event takes from here, bit for bit, what
/// the event left alone instead of computing it again.
struct CellRuleMemory {
  /// Whole cells' rules by a key of everything a cell's rule depends on (the options, its
  /// corners, the corners of the tetrahedra it clips, in order; a 64-bit hash, CacheKeyHasher).
  std::unordered_map<std::uint64_t, CellRule> cells;
  /// The shares of single tetrahedra in the mass reductions of the affine cells of more
  /// than a block of tetrahedra (reduction_block) a rebuild computed
  /// (tetrahedron_reductions.hpp): a pencil's tip cell, which the next cut cuts again, most
  /// of its tetrahedra unchanged. A set-up keeps none, nor a cell of fewer tetrahedra (a
  /// refinement's thousands of cut cells would each hold a reduction per tetrahedron).
  TetrahedronReductionMemory tetrahedra;
};

/// What compute_cell_rules reuses and remembers (each optional).
struct CellRuleReuse {
  const CellRuleMemory* previous = nullptr;  ///< rules and shares taken by key
  /// Receives the rule of every cell with tetrahedra, by key, and, with `previous` (a
  /// rebuild), the shares of the tetrahedra of every large affine cell whose mass
  /// reduction it computed (CellRuleMemory::tetrahedra).
  CellRuleMemory* computed = nullptr;
  /// Per cell, 1 where the material is already known to fill it (find_cell_pieces clipped
  /// it): the standard rule, without clipping its tetrahedra again.
  const std::vector<char>* filled = nullptr;
  int reused = 0;             ///< out: cells whose rule came from `previous`
  int integrated = 0;         ///< out: cells with tetrahedra whose rule was computed
  int reused_tetrahedra = 0;  ///< out: tetrahedra whose share of a reduction came from `previous`
};

/// background: the FCM mesh (hexahedra need planar faces); embedded: a tetrahedral
/// mesh of the object (corner nodes used). A cell counts as inside when its clipped
/// volume equals its own volume to filled_cell_tolerance relative. With `cell_tetrahedra` (one list per
/// cell), cell c clips exactly the embedded tetrahedra listed for it — a piece of a
/// background cell (piece_mesh.hpp) — instead of those the bucket grid finds near it.
/// Over several ranks every rank calls it alike: each computes every count()-th cell and
/// the rules are gathered (docs/scaling.md).
CellRules compute_cell_rules(const VolumeMesh& background, const VolumeMesh& embedded, const CellRuleOptions& options,
                             const std::vector<std::vector<int>>* cell_tetrahedra = nullptr,
                             CellRuleReuse* reuse = nullptr);

/// Recomputes the totals of `rules` (points, cell counts, failures, max residual) from its cells.
void sum_cell_rule_totals(CellRules& rules);

}  // namespace altfem
