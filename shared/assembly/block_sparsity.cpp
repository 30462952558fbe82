#include "shared/assembly/block_sparsity.hpp"

#include <algorithm>
#include <span>
#include <stdexcept>

namespace altfem {

// Three parallel passes over flat arrays (a 213,000-DOF Hex27 grid has 40 million
// entries): each basis function's neighbours from the groups that hold it, the pattern's
// rows column by column, and each group's pair offsets.
BlockSparsity::BlockSparsity(const TabulatedElements& elements, const BasisGroups& extra,
                             std::span<const char> included)
    : element_count_(elements.size()) {
  int basis_count = elements.basis_count();
  for (int g = 0; g < extra.size(); ++g)
    for (int index : extra[g]) basis_count = std::max(basis_count, index + 1);
  const int group_count = elements.size() + extra.size();
  if (!included.empty() && static_cast<int>(included.size()) != group_count)
    throw std::invalid_argument("BlockSparsity: one inclusion flag per element and extra group expected");
  // Group g's basis list (empty when left out): elements first, then the extra groups.
  const auto group = [&](int g) -> std::span<const int> {
    if (!included.empty() && !included[g]) return {};
    return g < elements.size() ? elements[g].basis : extra[g - elements.size()];
  };

  // The groups holding each basis function, in compressed rows.
  std::vector<long long> holder_starts(static_cast<size_t>(basis_count) + 1, 0);
  for (int g = 0; g < group_count; ++g)
    for (int column : group(g)) ++holder_starts[column + 1];
  for (int column = 0; column < basis_count; ++column) holder_starts[column + 1] += holder_starts[column];
  std::vector<int> holders(static_cast<size_t>(holder_starts.back()));
  {
    std::vector<long long> next(holder_starts.begin(), holder_starts.end() - 1);
    for (int g = 0; g < group_count; ++g)
      for (int column : group(g)) holders[next[column]++] = g;
  }

  // Each basis function's neighbours, ascending and unique, in one flat array: first the
  // room for every candidate (the groups' lists concatenated), then each function's run
  // sorted and made unique in place (a vector per function, grown by appending, had made
  // the pattern's set-up mostly allocation).
  std::vector<long long> candidate_starts(static_cast<size_t>(basis_count) + 1, 0);
  for (int column = 0; column < basis_count; ++column) {
    long long count = included.empty() ? 0 : 1;
    for (long long k = holder_starts[column]; k < holder_starts[column + 1]; ++k)
      count += static_cast<long long>(group(holders[k]).size());
    candidate_starts[column + 1] = candidate_starts[column] + count;
  }
  std::vector<int> neighbour_storage(static_cast<size_t>(candidate_starts.back()));
  std::vector<int> neighbour_counts(static_cast<size_t>(basis_count));
#pragma omp parallel for schedule(dynamic, 256)
  for (int column = 0; column < basis_count; ++column) {
    int* const first = neighbour_storage.data() + candidate_starts[column];
    int* last = first;
    if (!included.empty()) *last++ = column;
    for (long long k = holder_starts[column]; k < holder_starts[column + 1]; ++k) {
      const std::span<const int> basis = group(holders[k]);
      last = std::copy(basis.begin(), basis.end(), last);
    }
    std::sort(first, last);
    neighbour_counts[column] = static_cast<int>(std::unique(first, last) - first);
  }
  const auto neighbours = [&](int column) {
    return std::span<const int>(neighbour_storage.data() + candidate_starts[column],
                                static_cast<size_t>(neighbour_counts[column]));
  };

  // Column 3g+k starts after the 3 × 3 blocks of every basis function before g.
  const Eigen::Index dofs = 3 * static_cast<Eigen::Index>(basis_count);
  std::vector<long long> block_starts(static_cast<size_t>(basis_count) + 1, 0);
  for (int column = 0; column < basis_count; ++column)
    block_starts[column + 1] = block_starts[column] + 9 * static_cast<long long>(neighbour_counts[column]);
  const long long nonzeros = block_starts.back();
  pattern_.resize(dofs, dofs);
  pattern_.resizeNonZeros(nonzeros);
  auto* outer = pattern_.outerIndexPtr();
  auto* inner = pattern_.innerIndexPtr();
  double* values = pattern_.valuePtr();
#pragma omp parallel for schedule(dynamic, 256)
  for (int column = 0; column < basis_count; ++column) {
    const std::span<const int> list = neighbours(column);
    for (int k = 0; k < 3; ++k) {
      long long position = block_starts[column] + 3 * k * static_cast<long long>(list.size());
      outer[3 * column + k] = static_cast<int>(position);
      std::fill_n(values + position, 3 * list.size(), 0.0);
      for (int row : list)
        for (int i = 0; i < 3; ++i) inner[position++] = 3 * row + i;
    }
  }
  outer[dofs] = static_cast<int>(nonzeros);

  // Each group's pair offsets (#basis × #basis, column-major), at its own place.
  group_offsets_.resize(static_cast<size_t>(group_count) + 1);
  group_offsets_[0] = 0;
  for (int g = 0; g < group_count; ++g)
    group_offsets_[g + 1] = group_offsets_[g] + static_cast<long long>(group(g).size() * group(g).size());
  offsets_.resize(static_cast<size_t>(group_offsets_.back()));
#pragma omp parallel for schedule(dynamic, 64)
  for (int g = 0; g < group_count; ++g) {
    const std::span<const int> basis = group(g);
    long long position = group_offsets_[g];
    for (int column : basis) {
      const std::span<const int> list = neighbours(column);
      for (int row : basis)
        offsets_[position++] = 3 * static_cast<int>(std::lower_bound(list.begin(), list.end(), row) - list.begin());
    }
  }
}

}  // namespace altfem
