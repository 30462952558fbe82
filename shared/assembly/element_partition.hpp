#pragma once
// Which rank assembles which element in a run over several processes (docs/scaling.md):
// METIS's k-way partition of the element graph, two elements adjacent when they share a
// basis function or a method's term couples them (a DG face, a ghost-penalty face), each
// weighted by its assembly work, so that the ranks' shares cost about the same and few
// functions are shared across ranks.
#include <vector>

#include "shared/assembly/basis_groups.hpp"
#include "shared/assembly/tabulated_elements.hpp"
#include "shared/solve/graph_partition.hpp"

namespace altfem {

/// The part (0 … parts − 1) of each element (#elements), the same on every rank (rank 0's
/// partition, broadcast). Parts are contiguous where the element graph is connected.
/// Throws std::logic_error for parts > 1 in a build without METIS (which comes with PETSc).
std::vector<int> partition_elements(const TabulatedElements& elements, const BasisGroups& couplings, int parts);

}  // namespace altfem
