// `altfem info` names the libraries actually loaded, and warns about the reference BLAS.
#include <gtest/gtest.h>

#include "tests/cli/cli_support.hpp"

namespace altfem::test {
namespace {

TEST(Info, NamesVersionsAndTheLoadedBlas) {
  const auto result = run_altfem({"info"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  for (const char* word :
       {"altfem", "Eigen: 3.4", "CGAL: 5.5", "CHOLMOD", "PETSc: ", "MPI: ", "OpenMP threads", "BLAS", "fem"})
    EXPECT_NE(result.out.find(word), std::string::npos) << word << " missing from:\n" << result.out;
}

TEST(Info, ReferenceBlasIsNamedAndWarnedAbout) {
  const auto result = run_altfem({"info"}, "LD_LIBRARY_PATH=/usr/lib/x86_64-linux-gnu/blas");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("BLAS: reference"), std::string::npos) << result.out;
  EXPECT_NE(result.err.find("warning: the reference BLAS"), std::string::npos) << result.err;
}

// docs/conventions.md, "Threads": libgomp reads OMP_WAIT_POLICY before main(), so altfem
// restarts itself with it set to passive; a value the user chose is kept.
TEST(Info, RestartsWithPassiveOpenMpWaitingUnlessTheUserChoseAPolicy) {
  const auto unset = run_altfem({"info"}, "env -u OMP_WAIT_POLICY");
  ASSERT_EQ(unset.exit_code, 0) << unset.err;
  EXPECT_NE(unset.out.find("waiting passive\n"), std::string::npos) << unset.out;
  const auto chosen = run_altfem({"info"}, "OMP_WAIT_POLICY=active");
  ASSERT_EQ(chosen.exit_code, 0) << chosen.err;
  EXPECT_NE(chosen.out.find("waiting active\n"), std::string::npos) << chosen.out;
  EXPECT_NE(unset.out.find("BLAS core: "), std::string::npos) << unset.out;
}

}  // namespace
}  // namespace altfem::test
