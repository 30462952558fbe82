#include "shared/assembly/basis_incidence.hpp"

#include <algorithm>
#include <numeric>

namespace altfem {

BasisIncidence::BasisIncidence(const TabulatedElements& elements) : starts_(elements.basis_count() + 1, 0) {
  // Counting sort by basis function; visiting elements in order keeps each row sorted by element.
  for (int e = 0; e < elements.size(); ++e)
    for (int basis : elements[e].basis) ++starts_[basis + 1];
  for (std::size_t b = 1; b < starts_.size(); ++b) starts_[b] += starts_[b - 1];
  slots_.resize(static_cast<std::size_t>(starts_.back()));
  std::vector<long long> next(starts_.begin(), starts_.end() - 1);
  for (int e = 0; e < elements.size(); ++e) {
    const ElementView element = elements[e];
    for (int a = 0; a < element.basis_count(); ++a)
      slots_[static_cast<std::size_t>(next[element.basis[a]]++)] = elements.basis_offset(e) + a;
  }
  std::vector<double> mean_element(elements.basis_count(), 0.0);
  for (int e = 0; e < elements.size(); ++e)
    for (int basis : elements[e].basis) mean_element[basis] += e;
  for (int b = 0; b < elements.basis_count(); ++b)
    if (starts_[b + 1] > starts_[b]) mean_element[b] /= static_cast<double>(starts_[b + 1] - starts_[b]);
  gather_order_.resize(elements.basis_count());
  std::iota(gather_order_.begin(), gather_order_.end(), 0);
  std::stable_sort(gather_order_.begin(), gather_order_.end(),
                   [&](int left, int right) { return mean_element[left] < mean_element[right]; });
}

}  // namespace altfem
