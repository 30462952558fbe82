#include "bench/peak_memory.hpp"

#include <sys/resource.h>

namespace altfem::bench {

double peak_resident_gib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / (1024.0 * 1024.0);  // Linux reports KiB
}

}  // namespace altfem::bench
