#pragma once
// The number of elements a method holds, summed over the kinds it counts
// (MethodInstance::element_counts): what a cut or a refinement changes.
#include <nlohmann/json.hpp>

#include "shared/simulation/method_instance.hpp"

namespace altfem {

inline int element_count(const MethodInstance& method) {
  const nlohmann::json counts = method.element_counts();
  int count = 0;
  for (const auto& [kind, number] : counts.items()) count += number.get<int>();
  return count;
}

}  // namespace altfem
