#include "shared/solve/symmetric_from_upper.hpp"

#include "shared/solve/huge_page_allocation.hpp"

namespace altfem {

Eigen::SparseMatrix<double> symmetric_from_upper(const std::vector<UpperColumns>& ranges, int size) {
  std::vector<int> count(static_cast<size_t>(size), 0), strictly_upper(static_cast<size_t>(size), 0);
  for (const UpperColumns& upper : ranges)
    for (int j = upper.begin; j < upper.end; ++j)
      for (int at = upper.outer[j - upper.begin]; at < upper.outer[j - upper.begin + 1]; ++at) {
        const int i = upper.inner[at];
        ++count[j];
        if (i != j) {
          ++count[i];
          ++strictly_upper[j];
        }
      }
  Eigen::SparseMatrix<double> result(size, size);
  int* outer = result.outerIndexPtr();
  outer[0] = 0;
  for (int j = 0; j < size; ++j) outer[j + 1] = outer[j] + count[j];
  result.resizeNonZeros(outer[size]);
  int* inner = result.innerIndexPtr();
  double* value = result.valuePtr();
  advise_huge_pages(inner, sizeof(int) * static_cast<size_t>(outer[size]));  // not touched yet
  advise_huge_pages(value, sizeof(double) * static_cast<size_t>(outer[size]));

  std::vector<int> cursor(static_cast<size_t>(size)), lower_begin(static_cast<size_t>(size));
  for (int j = 0; j < size; ++j) cursor[j] = lower_begin[j] = outer[j] + strictly_upper[j];
  for (const UpperColumns& upper : ranges)
    for (int j = upper.begin; j < upper.end; ++j)
      for (int at = upper.outer[j - upper.begin]; at < upper.outer[j - upper.begin + 1]; ++at) {
        const int to = cursor[upper.inner[at]]++;
        inner[to] = j;
        value[to] = upper.value[at];
      }
  for (int j = 0; j < size; ++j) cursor[j] = outer[j];
  for (int i = 0; i < size; ++i)
    for (int at = lower_begin[i]; at < outer[i + 1]; ++at) {
      const int j = inner[at];
      if (j == i) continue;
      const int to = cursor[j]++;
      inner[to] = i;
      value[to] = value[at];
    }
  return result;
}

}  // namespace altfem
