#pragma once
#include <vector>

#include "shared/assembly/basis_groups.hpp"
#include "shared/assembly/tabulated_elements.hpp"

namespace altfem {

/// Groups the elements into colours such that no two elements of one colour share a
/// basis function (greedy, in element order). Assembling colour by colour, each colour
/// in parallel, needs no atomics or locks, and every matrix entry receives its
/// contributions in the same order whatever the thread count: results are identical
/// for 1 and 2 threads, not merely equal to round-off.
/// Returns the element indices of each colour.
std::vector<std::vector<int>> color_elements(const TabulatedElements& elements);
/// The same for any lists of basis functions (e.g. faces' couplings).
std::vector<std::vector<int>> color_groups(const BasisGroups& groups);

}  // namespace altfem
