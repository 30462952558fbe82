#include "shared/assembly/block_sparsity.hpp"

#include <algorithm>

namespace altfem {

BlockSparsity::BlockSparsity(const TabulatedElements& elements, const BasisGroups& extra)
    : element_count_(elements.size()) {
  int basis_count = elements.basis_count();
  for (int g = 0; g < extra.size(); ++g)
    for (int index : extra[g]) basis_count = std::max(basis_count, index + 1);
  // Every coupling group, elements first.
  const auto for_each_group = [&](auto&& body) {
    for (int e = 0; e < elements.size(); ++e) body(elements[e].basis);
    for (int g = 0; g < extra.size(); ++g) body(extra[g]);
  };

  std::vector<std::vector<int>> neighbours(basis_count);
  for_each_group([&](std::span<const int> basis) {
    for (int column : basis) neighbours[column].insert(neighbours[column].end(), basis.begin(), basis.end());
  });
  long long nonzeros = 0;
  for (auto& list : neighbours) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    nonzeros += 9 * static_cast<long long>(list.size());
  }

  const Eigen::Index dofs = 3 * static_cast<Eigen::Index>(basis_count);
  pattern_.resize(dofs, dofs);
  pattern_.resizeNonZeros(nonzeros);
  auto* outer = pattern_.outerIndexPtr();
  auto* inner = pattern_.innerIndexPtr();
  std::fill_n(pattern_.valuePtr(), nonzeros, 0.0);
  long long position = 0;
  for (int column = 0; column < basis_count; ++column)
    for (int k = 0; k < 3; ++k) {
      outer[3 * column + k] = static_cast<int>(position);
      for (int row : neighbours[column])
        for (int i = 0; i < 3; ++i) inner[position++] = 3 * row + i;
    }
  outer[dofs] = static_cast<int>(position);

  group_offsets_.reserve(elements.size() + extra.size() + 1);
  group_offsets_.push_back(0);
  for_each_group([&](std::span<const int> basis) {
    for (int column : basis) {
      const auto& list = neighbours[column];
      for (int row : basis)
        offsets_.push_back(3 * static_cast<int>(std::lower_bound(list.begin(), list.end(), row) - list.begin()));
    }
    group_offsets_.push_back(static_cast<long long>(offsets_.size()));
  });
}

}  // namespace altfem
