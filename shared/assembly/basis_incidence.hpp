#pragma once
// Which element slots each basis function occupies: the transpose of the
// element → basis lists of TabulatedElements, in compressed rows. A slot is the
// position of one (element, local basis function) pair in the packed basis lists,
// TabulatedElements::basis_offset(e) + a. Used to assemble vectors without colours:
// every element writes its local vector to its own slots in parallel, then every
// basis function sums its slots, so no two threads ever write the same entry.
#include <span>
#include <vector>

#include "shared/assembly/tabulated_elements.hpp"

namespace altfem {

class BasisIncidence {
public:
  explicit BasisIncidence(const TabulatedElements& elements);

  /// The slots of basis function `basis`, in increasing element order: summing in
  /// this order gives the same bits whatever the thread count.
  std::span<const long long> slots(int basis) const {
    return {slots_.data() + starts_[basis], static_cast<std::size_t>(starts_[basis + 1] - starts_[basis])};
  }
  /// Number of slots over all elements (Σ_e #basis_e).
  long long slot_count() const { return static_cast<long long>(slots_.size()); }
  /// The basis functions (#basis) sorted by the mean index of their elements. A
  /// parallel loop that splits elements and then this order into equal contiguous
  /// ranges gives each thread mostly the slots it wrote itself, which are still
  /// in its own cache (reading the other core's slots doubled the cost of the sums).
  const std::vector<int>& gather_order() const { return gather_order_; }

private:
  std::vector<long long> starts_;  // #basis functions + 1
  std::vector<long long> slots_;   // Σ_e #basis_e
  std::vector<int> gather_order_;  // #basis functions
};

}  // namespace altfem
