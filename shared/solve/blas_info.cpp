#include "shared/solve/blas_info.hpp"

#include <dlfcn.h>

#include <climits>
#include <cstdlib>

namespace altfem {

std::string blas_implementation_from_path(std::string_view path) {
  return path.find("/blas/libblas.so") != std::string_view::npos ? "reference" : "unknown";
}

BlasInfo loaded_blas() {
  BlasInfo info;
  // The object that dgemm_ resolves to is the one CHOLMOD calls. Several can be
  // loaded at once (e.g. the reference libblas.so.3 forced by LD_LIBRARY_PATH
  // next to OpenBLAS pulled in by liblapack.so.3), so a global lookup of an
  // OpenBLAS symbol would mislead; the lookups below go through dgemm_'s object.
  void* const dgemm = dlsym(RTLD_DEFAULT, "dgemm_");
  Dl_info where{};
  if (dgemm == nullptr || dladdr(dgemm, &where) == 0 || where.dli_fname == nullptr) {
    info.implementation = "unknown";
    return info;
  }
  char resolved[PATH_MAX];
  info.library = realpath(where.dli_fname, resolved) != nullptr ? resolved : where.dli_fname;
  // RTLD_NOLOAD: only a handle to the already loaded object; dlsym on it also
  // searches that object's dependencies (Debian's OpenBLAS libblas.so.3 forwards to libopenblas.so.0).
  void* const handle = dlopen(where.dli_fname, RTLD_LAZY | RTLD_NOLOAD);
  using ConfigFunction = char* (*)();
  using ThreadsFunction = int (*)();
  const auto config = handle ? reinterpret_cast<ConfigFunction>(dlsym(handle, "openblas_get_config")) : nullptr;
  const auto threads = handle ? reinterpret_cast<ThreadsFunction>(dlsym(handle, "openblas_get_num_threads")) : nullptr;
  if (config != nullptr) {
    info.implementation = config();
    if (info.implementation.rfind("OpenBLAS", 0) != 0) info.implementation = "OpenBLAS " + info.implementation;
    if (threads != nullptr) info.threads = threads();
  } else {
    info.implementation = blas_implementation_from_path(info.library);
  }
  if (handle != nullptr) dlclose(handle);
  return info;
}

bool is_reference_blas(const BlasInfo& info) { return info.implementation == "reference"; }

}  // namespace altfem
