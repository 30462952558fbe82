#pragma once
#include <algorithm>
#include <vector>

namespace altfem::bench {

/// The median of repeated measurements (the mean of the middle two for an even count);
/// docs/conventions.md, "Metrics": benchmarks report medians. 0 for none.
inline double median(std::vector<double> values) {
  if (values.empty()) return 0;
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  if (values.size() % 2 == 1) return *middle;
  return 0.5 * (*middle + *std::max_element(values.begin(), middle));
}

}  // namespace altfem::bench
