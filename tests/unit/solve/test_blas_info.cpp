#include "shared/solve/blas_info.hpp"
#include "shared/solve/linear_solver.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace altfem {
namespace {

// This machine runs Debian's OpenBLAS (libopenblas0-pthread), which takes over
// libblas.so.3 through the alternatives system (docs/environment.md, "BLAS").
TEST(BlasInfo, ReportsOpenBlasInThisProcess) {
  // Make sure CHOLMOD, hence its BLAS, is in use in this process.
  Eigen::SparseMatrix<double> matrix(1, 1);
  matrix.insert(0, 0) = 1.0;
  make_linear_solver({})->factorize(matrix);
  const BlasInfo blas = loaded_blas();
  EXPECT_EQ(blas.implementation.rfind("OpenBLAS ", 0), 0u) << blas.implementation;
  EXPECT_NE(blas.library.find("openblas"), std::string::npos) << blas.library;
  EXPECT_GE(blas.threads, 1);
  EXPECT_FALSE(is_reference_blas(blas));
}

TEST(BlasInfo, ReportsReferenceBlasUnderLibraryPathOverride) {
  const std::string command = "LD_LIBRARY_PATH=/usr/lib/x86_64-linux-gnu/blas '" ALTFEM_BLAS_PROBE "'";
  FILE* pipe = popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string output;
  char buffer[512];
  while (fgets(buffer, sizeof buffer, pipe) != nullptr) output += buffer;
  ASSERT_EQ(pclose(pipe), 0) << output;
  const std::string implementation = output.substr(0, output.find('\n'));
  EXPECT_EQ(implementation, "reference") << output;
  EXPECT_NE(output.find("/usr/lib/x86_64-linux-gnu/blas/libblas.so"), std::string::npos) << output;
}

TEST(BlasInfo, ClassifiesLibraryPaths) {
  EXPECT_EQ(blas_implementation_from_path("/usr/lib/x86_64-linux-gnu/blas/libblas.so.3.11.0"), "reference");
  EXPECT_EQ(blas_implementation_from_path("/opt/intel/mkl/lib/libmkl_rt.so"), "unknown");
  EXPECT_TRUE(is_reference_blas({"/usr/lib/x86_64-linux-gnu/blas/libblas.so.3", "reference", 1}));
}

}  // namespace
}  // namespace altfem
