#pragma once
// Octree quadrature for a level-set geometry in a hexahedral cell (Longva et al. 2020,
// §4.1): the reference cube is split recursively; an octant the level set proves
// entirely inside gets a Gauss rule, one entirely outside nothing, and a cut octant is
// split again until `depth`, where its rule keeps only the points inside. Its error is
// O(leaf size) for any leaf order: the reason §4.5 clips instead (docs/quadrature.md).
#include "shared/cut_cells/cut_cell_rule.hpp"
#include "shared/geometry/analytic_shape.hpp"

namespace altfem::fcm {

struct OctreeOptions {
  int depth = 4;       ///< subdivision levels for cut octants (0: the cell itself)
  int leaf_order = 4;  ///< strength of the tensor Gauss rule on every leaf
};

/// The rule on the cell's reference cube [-1,1]³ for ∫_{cell ∩ shape} f ≈ Σ w f(x(ξ))|J(ξ)|.
/// Octants are classified exactly for shapes whose level set is 1-Lipschitz (all of
/// analytic_shape.hpp's): inside if φ(centre) <= −r, outside if φ(centre) >= r, with r the
/// largest distance from the octant's physical centre to its corner images (the octant's
/// image lies in their convex hull, also for a trilinear map, so r bounds every point of
/// it). Throws std::invalid_argument
/// for a tetrahedral cell.
QuadratureRule octree_rule(const CellGeometry& cell, const AnalyticShape& shape, const OctreeOptions& options);

}  // namespace altfem::fcm
