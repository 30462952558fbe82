#pragma once
// Which BLAS the process runs on. CHOLMOD's supernodal factorisation spends its
// time in BLAS-3, and Debian's reference BLAS is ~10× slower than OpenBLAS, so
// `altfem info` and the benchmarks report it.
#include <string>
#include <string_view>

namespace altfem {

struct BlasInfo {
  /// Resolved path of the shared object that provides dgemm_ to this process, "" if none is loaded.
  std::string library;
  /// "OpenBLAS <version and build configuration>", "reference" or "unknown".
  std::string implementation;
  /// BLAS threads (1 unless OpenBLAS says otherwise).
  int threads = 1;
};

/// The BLAS loaded in this process (dlsym/dladdr of dgemm_, then OpenBLAS's
/// openblas_get_config / openblas_get_num_threads looked up from that object).
BlasInfo loaded_blas();

/// "reference" for Netlib's reference BLAS (Debian installs it under …/blas/),
/// "unknown" otherwise; used when the library exports no OpenBLAS symbols.
std::string blas_implementation_from_path(std::string_view path);

bool is_reference_blas(const BlasInfo& info);

}  // namespace altfem
