#pragma once
// Which elements a tabulator tabulates on this rank (ElementTabulator,
// docs/scaling.md), as one flag per element, asked once: the methods' tabulators read
// it inside their parallel loops.
#include <vector>

#include "shared/assembly/tabulated_elements.hpp"

namespace altfem {

/// held[e] = here(e) for e < count; every element when `here` is empty.
inline std::vector<char> tabulated_here(const TabulatedHere& here, int count) {
  std::vector<char> held(static_cast<size_t>(count), 1);
  if (here)
    for (int e = 0; e < count; ++e) held[e] = here(e) ? 1 : 0;
  return held;
}

}  // namespace altfem
