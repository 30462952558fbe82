#include "shared/assembly/element_coloring.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <span>

namespace altfem {

namespace {

// basis_of(item) is the std::span<const int> of an item's basis functions.
template <typename BasisOf>
std::vector<std::vector<int>> color_items(int count, int basis_count, BasisOf&& basis_of) {
  // One bit per colour per basis function, in words of 64 colours, grown on demand.
  int words = 1;
  std::vector<std::uint64_t> used(static_cast<size_t>(basis_count), 0);
  std::vector<std::vector<int>> colors;
  std::vector<std::uint64_t> forbidden;
  for (int element = 0; element < count; ++element) {
    const std::span<const int> basis = basis_of(element);
    int chosen = -1;
    forbidden.assign(words, 0);
    for (int node : basis)
      for (int w = 0; w < words; ++w) forbidden[w] |= used[static_cast<size_t>(node) * words + w];
    for (int w = 0; w < words && chosen < 0; ++w)
      if (~forbidden[w]) chosen = 64 * w + std::countr_one(forbidden[w]);
    if (chosen < 0) {
      // Every colour so far is taken around this element: widen the bit sets.
      std::vector<std::uint64_t> wider(used.size() / words * (words + 1), 0);
      for (size_t node = 0; node < used.size() / words; ++node)
        for (int w = 0; w < words; ++w) wider[node * (words + 1) + w] = used[node * words + w];
      used.swap(wider);
      chosen = 64 * words;
      ++words;
    }
    for (int node : basis) used[static_cast<size_t>(node) * words + chosen / 64] |= std::uint64_t{1} << (chosen % 64);
    if (chosen >= static_cast<int>(colors.size())) colors.resize(chosen + 1);
    colors[chosen].push_back(element);
  }
  return colors;
}

}  // namespace

std::vector<std::vector<int>> color_elements(const TabulatedElements& elements) {
  return color_items(elements.size(), elements.basis_count(), [&](int e) { return elements[e].basis; });
}

std::vector<std::vector<int>> color_groups(const BasisGroups& groups) {
  int basis_count = 0;
  for (int g = 0; g < groups.size(); ++g)
    for (int index : groups[g]) basis_count = std::max(basis_count, index + 1);
  return color_items(groups.size(), basis_count, [&](int g) { return groups[g]; });
}

}  // namespace altfem
