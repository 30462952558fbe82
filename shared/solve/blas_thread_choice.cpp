#include "shared/solve/blas_thread_choice.hpp"

#include <omp.h>
#include <sched.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

namespace altfem {

int factorisation_blas_threads(double flops, int thread_limit, int cores, int busy_elsewhere) {
  if (flops < minimum_flops_for_blas_threads) return 1;
  return std::max(1, std::min(thread_limit, cores - busy_elsewhere));
}

std::optional<int> runnable_threads_in_loadavg(const std::string& text) {
  std::istringstream fields(text);
  double averages[3];
  int runnable = 0;
  char slash = 0;
  if (!(fields >> averages[0] >> averages[1] >> averages[2] >> runnable >> slash) || slash != '/') return std::nullopt;
  return runnable;
}

bool thread_stat_is_runnable(const std::string& text) {
  const std::size_t close = text.rfind(')');
  return close != std::string::npos && close + 2 < text.size() && text[close + 2] == 'R';
}

namespace {

int runnable_threads_elsewhere_now() {
  std::ifstream loadavg("/proc/loadavg");
  std::string line;
  std::optional<int> runnable;
  if (std::getline(loadavg, line)) runnable = runnable_threads_in_loadavg(line);
  if (!runnable) return 0;
  int own = 0;
  std::error_code error;
  for (const auto& task : std::filesystem::directory_iterator("/proc/self/task", error)) {
    std::ifstream stat(task.path() / "stat");
    if (std::getline(stat, line) && thread_stat_is_runnable(line)) ++own;
  }
  return std::max(0, *runnable - own);
}

}  // namespace

int runnable_threads_elsewhere() {
  int fewest = runnable_threads_elsewhere_now();
  for (int sample = 1; sample < 3 && fewest > 0; ++sample) {
    std::this_thread::sleep_for(std::chrono::microseconds(500));
    fewest = std::min(fewest, runnable_threads_elsewhere_now());
  }
  return fewest;
}

int usable_cores() {
  cpu_set_t mask;
  if (sched_getaffinity(0, sizeof(mask), &mask) != 0) return std::max(1, omp_get_num_procs());
  return std::max(1, CPU_COUNT(&mask));
}

int blas_thread_limit() {
  if (const char* value = std::getenv("OPENBLAS_NUM_THREADS")) {
    const int threads = std::atoi(value);
    if (threads > 0) return threads;
  }
  return omp_get_max_threads();
}

}  // namespace altfem
