#include "shared/solve/blas_threads.hpp"

#include <dlfcn.h>

namespace altfem {

void park_blas_threads() {
  // Looked up at run time: the BLAS is chosen by Debian's alternatives when the
  // program starts, not when it is built (blas_info.hpp), and OpenBLAS declares this
  // function in no header.
  using ShutdownFunction = int (*)();
  static const auto shutdown = reinterpret_cast<ShutdownFunction>(dlsym(RTLD_DEFAULT, "blas_thread_shutdown_"));
  if (shutdown != nullptr) shutdown();
}

void set_blas_threads(int count) {
  using SetFunction = void (*)(int);
  static const auto set = reinterpret_cast<SetFunction>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  if (set != nullptr) set(count);
}

}  // namespace altfem
