#pragma once
// Union–find with path halving: connected pieces of a cut cell, groups of merged cells.
#include <numeric>
#include <vector>

namespace altfem {

class DisjointSets {
public:
  explicit DisjointSets(int count) : parent_(static_cast<std::size_t>(count)) {
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  int find(int element) {
    while (parent_[element] != element) element = parent_[element] = parent_[parent_[element]];
    return element;
  }
  /// Joins the two sets; the root of `kept`'s set stays the root.
  void join(int kept, int other) { parent_[find(other)] = find(kept); }

private:
  std::vector<int> parent_;
};

}  // namespace altfem
