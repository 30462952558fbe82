#pragma once
#include <filesystem>

namespace altfem {

/// The folder with the data altfem reads at run time (quadrature tables): the
/// ALTFEM_DATA_DIR environment variable if set, else the repository's data/.
std::filesystem::path data_directory();

/// altfem's version string, e.g. "0.1.0".
const char* version();

}  // namespace altfem
