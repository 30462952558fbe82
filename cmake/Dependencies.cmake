# Every dependency, each with an error that names the Debian package to install
# (scripts/setup installs them all).

macro(altfem_require found package)
  if(NOT ${found})
    message(FATAL_ERROR "altfem: ${ARGN} not found; install the Debian package '${package}' (or run scripts/setup)")
  endif()
endmacro()

find_package(Eigen3 3.4 QUIET NO_MODULE)
altfem_require(Eigen3_FOUND libeigen3-dev "Eigen 3.4")

find_package(CGAL 5.5 QUIET)
altfem_require(CGAL_FOUND libcgal-dev "CGAL 5.5")

find_package(OpenMP QUIET)
altfem_require(OpenMP_CXX_FOUND libomp-dev "OpenMP")

find_package(nlohmann_json 3.11 QUIET)
altfem_require(nlohmann_json_FOUND nlohmann-json3-dev "nlohmann-json 3.11")

find_package(CLI11 QUIET)
altfem_require(CLI11_FOUND libcli11-dev "CLI11")

# COIN-OR Clp (the simplex LP of quadrature simplification) has only a pkg-config file.
find_package(PkgConfig QUIET)
altfem_require(PKG_CONFIG_FOUND pkg-config "pkg-config")
pkg_check_modules(CLP QUIET IMPORTED_TARGET clp)
altfem_require(CLP_FOUND coinor-libclp-dev "COIN-OR Clp")
# muParser (the scene's expressions of x, y, z, t; deal.II's FunctionParser uses it).
pkg_check_modules(MUPARSER QUIET IMPORTED_TARGET muparser)
altfem_require(MUPARSER_FOUND libmuparser-dev "muParser")

# PETSc (solver.linear "petsc"): Debian's build has hypre and MUMPS, over Open MPI.
if(ALTFEM_PETSC)
  pkg_check_modules(PETSC QUIET PETSc)
  altfem_require(PETSC_FOUND libpetsc-real3.18-dev "PETSc")
  find_package(MPI QUIET COMPONENTS CXX)
  altfem_require(MPI_CXX_FOUND libopenmpi-dev "MPI")
  # METIS partitions the elements and the matrix rows among the ranks of an mpirun
  # (shared/solve/graph_partition.hpp).
  find_path(METIS_INCLUDE_DIR metis.h)
  find_library(METIS_LIBRARY metis)
  set(METIS_OK FALSE)
  if(METIS_INCLUDE_DIR AND METIS_LIBRARY)
    set(METIS_OK TRUE)
  endif()
  altfem_require(METIS_OK libmetis-dev "METIS")
endif()

# SuiteSparse 5 on Debian ships neither a CMake config nor a .pc file.
find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
find_library(CHOLMOD_LIBRARY cholmod)
find_library(UMFPACK_LIBRARY umfpack)
find_library(SUITESPARSECONFIG_LIBRARY suitesparseconfig)
set(SUITESPARSE_OK FALSE)
if(CHOLMOD_INCLUDE_DIR AND CHOLMOD_LIBRARY AND UMFPACK_LIBRARY AND SUITESPARSECONFIG_LIBRARY)
  set(SUITESPARSE_OK TRUE)
endif()
altfem_require(SUITESPARSE_OK libsuitesparse-dev "SuiteSparse (CHOLMOD, UMFPACK)")
add_library(altfem_suitesparse INTERFACE)
target_include_directories(altfem_suitesparse INTERFACE ${CHOLMOD_INCLUDE_DIR})
target_link_libraries(altfem_suitesparse INTERFACE ${CHOLMOD_LIBRARY} ${UMFPACK_LIBRARY} ${SUITESPARSECONFIG_LIBRARY})

if(ALTFEM_TESTS)
  find_package(GTest QUIET)
  altfem_require(GTest_FOUND libgtest-dev "GoogleTest")
endif()
if(ALTFEM_BENCHMARKS)
  find_package(benchmark QUIET)
  altfem_require(benchmark_FOUND libbenchmark-dev "Google Benchmark")
endif()
