#include "shared/simulation/progress.hpp"

#include <unistd.h>

#include <cstdio>

#include "shared/solve/process_ranks.hpp"

namespace altfem {

Progress::Progress(int total_steps)
    : total_(total_steps),
      enabled_(isatty(STDERR_FILENO) == 1 && ranks::index() == 0),
      start_(std::chrono::steady_clock::now()) {}

Progress::~Progress() {
  if (printed_) std::fputc('\n', stderr);
}

void Progress::update(int step, int newton_iterations) {
  if (!enabled_) return;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double eta = step > 0 ? elapsed / step * (total_ - step) : 0.0;
  std::fprintf(stderr, "\rstep %d/%d  Newton iterations %d  elapsed %.1f s  ETA %.1f s   ", step, total_,
               newton_iterations, elapsed, eta);
  std::fflush(stderr);
  printed_ = true;
}

}  // namespace altfem
