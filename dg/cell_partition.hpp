#pragma once
// Which rank integrates which DG cell in a run over several processes (docs/scaling.md):
// METIS's partition of the cells' face graph, each cell weighted by what its matrices
// cost, so that the ranks' shares of the exact integration cost about the same.
#include <array>
#include <vector>

#include "dg/monomial_basis.hpp"
#include "shared/geometry/polyhedron.hpp"

namespace altfem::dg {

/// The part (0 … parts − 1) of each cell (#cells), the same on every rank. couplings: the
/// pairs of cells that share a face. A cell's weight is n² × (1 + #faces), n its functions:
/// its volume matrix and a share of its faces'.
std::vector<int> partition_cells(const std::vector<Polyhedron>& cells, const std::vector<MonomialBasis>& bases,
                                 const std::vector<std::array<int, 2>>& couplings, int parts);

}  // namespace altfem::dg
