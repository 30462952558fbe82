#include "shared/solve/factor_memory.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "shared/common/error.hpp"

namespace altfem {

double available_memory_bytes() {
  std::ifstream meminfo("/proc/meminfo");
  std::string line;
  while (std::getline(meminfo, line)) {
    std::istringstream fields(line);
    std::string key;
    double kibibytes = 0;
    if (fields >> key >> kibibytes && key == "MemAvailable:") return 1024.0 * kibibytes;
  }
  return 0;
}

void require_factor_fits(double factor_entries, double factor_bytes, double available_bytes) {
  if (available_bytes <= 0 || factor_bytes <= available_bytes) return;
  char message[360];
  std::snprintf(message, sizeof(message),
                "the Cholesky factor needs %.1f GB (%.3g entries), more than the %.1f GB of memory available: "
                "set solver.linear to \"petsc\" (CG + algebraic multigrid) or \"pcg\" (iterative solvers store no "
                "factor) or use a coarser "
                "discretization",
                factor_bytes / 1e9, factor_entries, available_bytes / 1e9);
  throw NumericalError(message);
}

}  // namespace altfem
