#pragma once
// Lists of basis functions that couple all-to-all, packed into one array: the basis
// functions of a face's two neighbours (DG fluxes, ghost penalties), or any other block
// coupling a method adds to its elements' (docs/architecture.md, "Adding a method").
#include <span>
#include <vector>

namespace altfem {

class BasisGroups {
public:
  void add(std::span<const int> basis) {
    basis_.insert(basis_.end(), basis.begin(), basis.end());
    offsets_.push_back(static_cast<long long>(basis_.size()));
  }
  int size() const { return static_cast<int>(offsets_.size()) - 1; }
  std::span<const int> operator[](int group) const {
    return {basis_.data() + offsets_[group], static_cast<size_t>(offsets_[group + 1] - offsets_[group])};
  }

private:
  std::vector<long long> offsets_{0};  // #groups + 1
  std::vector<int> basis_;
};

}  // namespace altfem
