#include "shared/common/data_directory.hpp"

#include <cstdlib>

namespace altfem {

std::filesystem::path data_directory() {
  if (const char* overridden = std::getenv("ALTFEM_DATA_DIR"); overridden && *overridden) return overridden;
  return ALTFEM_DATA_DIR;
}

const char* version() { return ALTFEM_VERSION; }

}  // namespace altfem
