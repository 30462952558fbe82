#include "shared/assembly/element_coloring.hpp"

#include <bit>
#include <cstdint>

namespace altfem {

std::vector<std::vector<int>> color_elements(const TabulatedElements& elements) {
  // One bit per colour per basis function, in words of 64 colours, grown on demand.
  int words = 1;
  std::vector<std::uint64_t> used(static_cast<size_t>(elements.basis_count()), 0);
  std::vector<std::vector<int>> colors;
  std::vector<std::uint64_t> forbidden;
  for (int element = 0; element < elements.size(); ++element) {
    const auto basis = elements[element].basis;
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

}  // namespace altfem
