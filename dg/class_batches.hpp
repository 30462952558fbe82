#pragma once
// Matrices computed once per class of items (cells or faces that are translates of each
// other, dg/cell_similarity.hpp) and used for every item of the class, in order, without
// holding every class's matrix at once.
#include <Eigen/Core>
#include <algorithm>
#include <exception>
#include <vector>

namespace altfem::dg {

// Items whose classes' matrices are computed in parallel before they are added into K:
// bounds the matrices held at once (a cut cell's faces are mostly classes of one).
inline constexpr int class_batch_size = 256;

// use(item, matrix) for every item in order whose class (classes[item]) is not -1, the
// matrix of a class computed once by compute(representative item) — in parallel for the
// classes first met in a batch of items — and freed after the class's last item.
template <typename Compute, typename Use>
void for_each_item_by_class(const std::vector<int>& classes, int class_count, Compute&& compute, Use&& use) {
  const int items = static_cast<int>(classes.size());
  std::vector<int> representative(class_count, -1), last(class_count, -1);
  for (int item = 0; item < items; ++item) {
    if (classes[item] < 0) continue;
    if (representative[classes[item]] < 0) representative[classes[item]] = item;
    last[classes[item]] = item;
  }
  std::vector<Eigen::MatrixXd> matrices(class_count);
  std::vector<int> first_met;
  for (int start = 0; start < items; start += class_batch_size) {
    const int end = std::min(items, start + class_batch_size);
    first_met.clear();
    for (int item = start; item < end; ++item)
      if (classes[item] >= 0 && representative[classes[item]] == item) first_met.push_back(item);
    std::exception_ptr failure;  // bad input (a face of < 3 vertices, say) must not leave the region
#pragma omp parallel for schedule(dynamic, 4) if (first_met.size() > 8)
    for (size_t k = 0; k < first_met.size(); ++k) {
      try {
        matrices[classes[first_met[k]]] = compute(first_met[k]);
      } catch (...) {
#pragma omp critical(dg_linear_system_failure)
        if (!failure) failure = std::current_exception();
      }
    }
    if (failure) std::rethrow_exception(failure);
    for (int item = start; item < end; ++item) {
      if (classes[item] < 0) continue;
      Eigen::MatrixXd& matrix = matrices[classes[item]];
      use(item, matrix);
      if (last[classes[item]] == item) matrix = Eigen::MatrixXd();
    }
  }
}

}  // namespace altfem::dg
