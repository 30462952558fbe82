#include <CGAL/version.h>
#include <cholmod.h>
#include <omp.h>

#include <Eigen/Core>
#include <cstdio>
#include <cstdlib>

#include "app/commands.hpp"
#include "app/method_registry.hpp"
#include "app/process_environment.hpp"
#include "shared/common/data_directory.hpp"
#include "shared/solve/blas_core_type.hpp"
#include "shared/solve/blas_info.hpp"
#include "shared/solve/blas_thread_choice.hpp"
#include "shared/solve/petsc_solver.hpp"
#include "shared/solve/process_ranks.hpp"

namespace altfem::cli {

int info_command() {
  std::printf("altfem %s\n", version());
#if defined(__clang__)
  std::printf("compiler: clang %s\n", __clang_version__);
#elif defined(__GNUC__)
  std::printf("compiler: gcc %d.%d.%d\n", __GNUC__, __GNUC_MINOR__, __GNUC_PATCHLEVEL__);
#endif
  std::printf("build type: %s\n", ALTFEM_BUILD_TYPE);
  const char* wait_policy = std::getenv("OMP_WAIT_POLICY");
  std::printf("OpenMP threads: %d, waiting %s\n", omp_get_max_threads(),
              wait_policy != nullptr ? wait_policy : "libgomp's default");
  std::printf("Eigen: %d.%d.%d\n", EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION);
  std::printf("CGAL: %s\n", CGAL_VERSION_STR);
  int cholmod[3] = {0, 0, 0};
  cholmod_version(cholmod);
  std::printf("SuiteSparse: %d.%d.%d (CHOLMOD %d.%d.%d)\n", SUITESPARSE_MAIN_VERSION, SUITESPARSE_SUB_VERSION,
              SUITESPARSE_SUBSUB_VERSION, cholmod[0], cholmod[1], cholmod[2]);
  std::printf("PETSc: %s\n", petsc_available() ? (petsc_version() + " (solver.linear \"petsc\")").c_str()
                                               : "not in this build (-DALTFEM_PETSC=OFF)");
  std::printf("MPI: %s\n", ranks::library().empty()
                               ? "not in this build (it comes with PETSc)"
                               : (ranks::library() + " (mpirun -n N altfem run, docs/scaling.md)").c_str());
  const BlasInfo blas = loaded_blas();
  std::printf("BLAS: %s (%s), %d thread%s\n", blas.implementation.c_str(), blas.library.c_str(), blas.threads,
              blas.threads == 1 ? "" : "s");
  std::printf("BLAS core: %s%s%s\n", loaded_openblas_core().empty() ? "(not OpenBLAS)" : loaded_openblas_core().c_str(),
              *openblas_core_choice() != '\0' ? ", chosen by altfem: " : "", openblas_core_choice());
  std::printf(
      "BLAS threads (docs/conventions.md, \"Threads\"): solves 1; factorisations of %.0e operations or more "
      "up to %d on %d cores, less the %d threads other processes run now\n",
      minimum_flops_for_blas_threads, blas_thread_limit(), usable_cores(), runnable_threads_elsewhere());
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
