#include <CGAL/version.h>
#include <cholmod.h>
#include <omp.h>

#include <Eigen/Core>
#include <cstdio>

#include "app/commands.hpp"
#include "app/method_registry.hpp"
#include "shared/common/data_directory.hpp"
#include "shared/solve/blas_info.hpp"

namespace altfem::cli {

int info_command() {
  std::printf("altfem %s\n", version());
#if defined(__clang__)
  std::printf("compiler: clang %s\n", __clang_version__);
#elif defined(__GNUC__)
  std::printf("compiler: gcc %d.%d.%d\n", __GNUC__, __GNUC_MINOR__, __GNUC_PATCHLEVEL__);
#endif
  std::printf("build type: %s\n", ALTFEM_BUILD_TYPE);
  std::printf("OpenMP threads: %d\n", omp_get_max_threads());
  std::printf("Eigen: %d.%d.%d\n", EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION);
  std::printf("CGAL: %s\n", CGAL_VERSION_STR);
  int cholmod[3] = {0, 0, 0};
  cholmod_version(cholmod);
  std::printf("SuiteSparse: %d.%d.%d (CHOLMOD %d.%d.%d)\n", SUITESPARSE_MAIN_VERSION, SUITESPARSE_SUB_VERSION,
              SUITESPARSE_SUBSUB_VERSION, cholmod[0], cholmod[1], cholmod[2]);
  const BlasInfo blas = loaded_blas();
  std::printf("BLAS: %s (%s), %d thread%s\n", blas.implementation.c_str(), blas.library.c_str(), blas.threads,
              blas.threads == 1 ? "" : "s");
  if (is_reference_blas(blas))
    std::fprintf(stderr,
                 "altfem: warning: the reference BLAS is loaded: CHOLMOD runs ~10x slower; install "
                 "libopenblas0-pthread\n");
  std::printf("data: %s\n", data_directory().c_str());
  std::string methods;
  for (const auto& name : available_methods()) methods += (methods.empty() ? "" : ", ") + name;
  std::printf("methods: %s\n", methods.c_str());
  return 0;
}

}  // namespace altfem::cli
