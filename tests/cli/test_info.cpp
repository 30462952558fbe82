// `altfem info` names the libraries actually loaded, and warns about the reference BLAS.
#include <gtest/gtest.h>

#include "tests/cli/cli_support.hpp"

namespace altfem::test {
namespace {

TEST(Info, NamesVersionsAndTheLoadedBlas) {
  const auto result = run_altfem({"info"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  for (const char* word : {"altfem", "Eigen: 3.4", "CGAL: 5.5", "CHOLMOD", "OpenMP threads", "BLAS", "fem"})
    EXPECT_NE(result.out.find(word), std::string::npos) << word << " missing from:\n" << result.out;
}

TEST(Info, ReferenceBlasIsNamedAndWarnedAbout) {
  const auto result = run_altfem({"info"}, "LD_LIBRARY_PATH=/usr/lib/x86_64-linux-gnu/blas");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("BLAS: reference"), std::string::npos) << result.out;
  EXPECT_NE(result.err.find("warning: the reference BLAS"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace altfem::test
