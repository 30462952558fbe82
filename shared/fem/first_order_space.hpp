#pragma once
// The first-order Lagrange space inside a higher-order one on the same mesh (Tet4 in
// Tet10 and Tet20, Hex8 in Hex20 and Hex27): the coarse level of a p-multigrid. Algebraic
// multigrid aggregates a quadratic element's nodes poorly (GAMG: 45-60 CG iterations on
// Hex20 and Tet10 cantilevers against 23-28 on Hex8, docs/performance.md); on the
// first-order space it works as on a first-order mesh, and a smoother on the fine space
// removes what the coarse one cannot hold (the high-order oscillations inside elements).
// Multigrid in the polynomial degree: Rønquist & Patera 1987; algebraic multigrid on the
// lowest order of higher-order elements: Heys, Manteuffel, McCormick & Olson 2005.
#include "shared/mesh/node_constraints.hpp"
#include "shared/mesh/volume_mesh.hpp"
#include "shared/solve/coarse_space.hpp"

namespace altfem {

/// The first-order space on `mesh`'s corner nodes: row a of the prolongation is the
/// first-order basis of a cell holding node a at its reference position (the same in
/// every cell holding it: the first-order space is conforming). Empty for a first-order
/// mesh. Basis function a is mesh node a (tabulate_lagrange).
///
/// With hanging nodes (`constraints`, may be null: a refined grid's), the first-order space
/// with its own hanging nodes, as a first-order refined grid has them: its functions are
/// the free nodes that every cell holds as a corner; a free node some coarser cell holds
/// otherwise (its mid-edge node where finer cells have a corner) takes that cell's
/// first-order values, and a hanging node its masters'. Rows: the free nodes only, the
/// fine space's functions; every coarse function is first order on every cell.
CoarseSpace first_order_space(const VolumeMesh& mesh, const NodeConstraints* constraints = nullptr);

}  // namespace altfem
