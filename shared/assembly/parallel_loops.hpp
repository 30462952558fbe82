#pragma once
// The loop shapes the assemblers share (internal header): lock-free parallel loops over
// elements or faces, and the first failure of such a loop (exceptions must not leave an
// OpenMP region).
#include <atomic>
#include <cstddef>
#include <vector>

namespace altfem::parallel {

// Below this many items a parallel region costs more than it saves (on a busy
// machine each can wait a whole time slice), and even a one-thread region allocates
// its team in libgomp, so small loops do not enter one at all.
constexpr size_t minimum_parallel_items = 64;

/// The first item, in item order, that failed in a parallel loop.
class FirstFailure {
public:
  void record(int item) {
    int current = item_.load();
    while ((current < 0 || item < current) && !item_.compare_exchange_weak(current, item)) {
    }
  }
  int item() const { return item_.load(); }

private:
  std::atomic<int> item_{-1};
};

/// body(i) for i < count, in parallel when there is enough work. Items cost the
/// same, so a static split balances best (dynamic chunks left one thread idle).
template <typename Body>
void for_each_index(size_t count, int threads, Body&& body) {
  if (count < minimum_parallel_items || threads == 1) {
    for (size_t i = 0; i < count; ++i) body(i);
    return;
  }
#pragma omp parallel for schedule(static) num_threads(threads)
  for (size_t i = 0; i < count; ++i) body(i);
}

/// first(i) for every i < first_count, then, once all of them are done, second(j)
/// for every j < second_count: one parallel region with a barrier between the two
/// loops costs less than two regions.
template <typename First, typename Second>
void for_each_index_in_two_passes(size_t first_count, First&& first, size_t second_count, Second&& second,
                                  int threads) {
  if (first_count < minimum_parallel_items || threads == 1) {
    for (size_t i = 0; i < first_count; ++i) first(i);
    for (size_t j = 0; j < second_count; ++j) second(j);
    return;
  }
#pragma omp parallel num_threads(threads)
  {
#pragma omp for schedule(static)
    for (size_t i = 0; i < first_count; ++i) first(i);
#pragma omp for schedule(static)
    for (size_t j = 0; j < second_count; ++j) second(j);
  }
}

/// body(item) for every item, colour by colour: within a colour no two items share a
/// basis function, so they scatter without locks and every entry sums in the same
/// order. One parallel region for all colours: a barrier between colours costs less
/// than a new region. Every colour ends in a barrier, so the work per colour, not the
/// total, decides: a 187-tet mesh in 20 colours took 0.3 s per assembly on a loaded
/// 2-core machine in parallel, 0.3 ms serially.
template <typename Body>
void for_each_colored(const std::vector<std::vector<int>>& colors, size_t total, int threads, Body&& body) {
  if (threads == 1 || total < minimum_parallel_items * colors.size()) {
    for (const auto& color : colors)
      for (int item : color) body(item);
    return;
  }
#pragma omp parallel num_threads(threads)
  for (const auto& color : colors) {
#pragma omp for schedule(static)
    for (size_t index = 0; index < color.size(); ++index) body(color[index]);
  }
}

}  // namespace altfem::parallel
