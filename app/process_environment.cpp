#include "app/process_environment.hpp"

#include <unistd.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "shared/solve/blas_core_type.hpp"

namespace altfem::cli {
namespace {

// Passed to the restarted process so `altfem info` can say which core OpenBLAS had picked.
constexpr const char* chosen_core_note = "ALTFEM_OPENBLAS_CORETYPE_CHOICE";

}  // namespace

void restart_with_tuned_environment(char** argv) {
  std::vector<const char*> set;
  if (std::getenv("OMP_WAIT_POLICY") == nullptr) {
    setenv("OMP_WAIT_POLICY", "passive", 1);
    set.push_back("OMP_WAIT_POLICY");
  }
  if (std::getenv("OPENBLAS_CORETYPE") == nullptr) {
    const std::string core = better_openblas_core_here();
    if (!core.empty()) {
      const std::string note = "OPENBLAS_CORETYPE=" + core + " (OpenBLAS had picked " + loaded_openblas_core() + ")";
      setenv("OPENBLAS_CORETYPE", core.c_str(), 1);
      setenv(chosen_core_note, note.c_str(), 1);
      set.insert(set.end(), {"OPENBLAS_CORETYPE", chosen_core_note});
    }
  }
  if (set.empty()) return;
  execv("/proc/self/exe", argv);
  // Not restarted: libgomp and OpenBLAS keep what they chose, and the reports must say so.
  for (const char* name : set) unsetenv(name);
}

const char* openblas_core_choice() {
  const char* note = std::getenv(chosen_core_note);
  return note != nullptr ? note : "";
}

}  // namespace altfem::cli
