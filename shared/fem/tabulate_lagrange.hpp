#pragma once
#include <unordered_map>
#include <vector>

#include "shared/assembly/tabulated_discretization.hpp"
#include "shared/assembly/tabulated_elements.hpp"
#include "shared/mesh/node_constraints.hpp"
#include "shared/mesh/volume_mesh.hpp"
#include "shared/quadrature/quadrature_rule.hpp"

namespace altfem {

/// The quadrature of each cell of a Lagrange mesh, in the reference element's
/// coordinates, and its material. `fem` uses one rule for all cells; the FCM keeps the
/// standard rule for inside cells and gives each cut cell its own (Longva et al.
/// 2020 §4), which is why the rule is looked up per cell.
struct LagrangeCellRules {
  QuadratureRule standard;                         ///< every cell not in `custom`
  std::unordered_map<int, QuadratureRule> custom;  ///< cell → its own rule
  std::vector<int> materials;                      ///< #cells material ids; empty: all 0
};

/// Tabulates a conforming Lagrange mesh: for each cell, weights w_q |det J(ξ_q)|, basis
/// values, and physical gradients ∇N = (∂N/∂ξ) J⁻¹ at its rule's points. Basis function
/// i is mesh node i. OpenMP-parallel over cells. Throws NumericalError naming the cell
/// and point when det J ≤ 0 (an inverted or degenerate cell). A cell `here` does not hold is
/// added with its nodes and point count only (TabulatedElements::add_held_elsewhere). With
/// `constraints` (null or empty for none), the hanging nodes' functions are handed to their
/// masters (substitute_hanging): a cell's basis is then its free nodes and the masters of its
/// hanging ones (an element without hanging nodes stays bit for bit as without constraints).
TabulatedElements tabulate_lagrange(const VolumeMesh& mesh, const LagrangeCellRules& rules,
                                    const TabulatedHere& here = nullptr, const NodeConstraints* constraints = nullptr);
/// The tabulator of a TabulatedDiscretization (DiscretizationParts::tabulate) of a Lagrange
/// mesh: tabulate_lagrange with the cells a rank holds and the hanging nodes of
/// `constraints`. `mesh` and `constraints` must outlive it.
ElementTabulator lagrange_tabulator(const VolumeMesh& mesh, LagrangeCellRules rules,
                                    const NodeConstraints* constraints = nullptr);
/// Every cell with the reference rule of `quadrature_strength` (tet_rule / hex_rule), material 0.
TabulatedElements tabulate_lagrange(const VolumeMesh& mesh, int quadrature_strength,
                                    const NodeConstraints* constraints = nullptr);

}  // namespace altfem
