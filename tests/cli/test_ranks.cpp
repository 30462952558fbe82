// `mpirun -n 2 altfem run` (issue #37, step 2; docs/scaling.md): two processes assemble
// their halves of the elements and PETSc solves across them, and the run is the
// one-process run: one summary, one set of frames, rank 0's line, the same energy.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "tests/cli/cli_support.hpp"

namespace altfem::test {
namespace {

#ifndef ALTFEM_HAVE_PETSC
#define SKIP_WITHOUT_MPI() GTEST_SKIP() << "built without PETSc and MPI (-DALTFEM_PETSC=OFF)"
#else
#define SKIP_WITHOUT_MPI() (void)0
#endif

std::vector<std::string> file_names(const std::filesystem::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) names.push_back(entry.path().filename());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(Ranks, TwoRanksWriteTheOneRankRun) {
  SKIP_WITHOUT_MPI();
  const auto folder = fresh_directory("two-ranks");
  const std::vector<std::string> scene{"run",      source_path("scenes/cantilever.json").string(),
                                       "--method", "fem",
                                       "--set",    "solver/linear=petsc",
                                       "--set",    "solver/linear_tolerance=1e-12",
                                       "--out"};
  std::vector<std::string> one = scene, two = scene;
  one.push_back((folder / "one").string());
  two.push_back((folder / "two").string());
  const auto alone = run_altfem(one);
  ASSERT_EQ(alone.exit_code, 0) << alone.err;
  const auto together = run_altfem_on_ranks(2, two);
  ASSERT_EQ(together.exit_code, 0) << together.err;
  EXPECT_EQ(lines_of(together.out).size(), 1u) << "rank 0 alone reports:\n" << together.out;
  EXPECT_EQ(file_names(folder / "two"), file_names(folder / "one"));

  const auto summary = read_summary(folder / "two");
  EXPECT_EQ(summary["ranks"]["count"], 2);
  for (const char* phase : {"assembly", "analysis", "factorisation", "solve", "total"}) {
    ASSERT_EQ(summary["ranks"]["timings_s"][phase].size(), 2u) << phase;
    for (const auto& seconds : summary["ranks"]["timings_s"][phase]) EXPECT_GE(seconds.get<double>(), 0.0) << phase;
  }
  EXPECT_FALSE(read_summary(folder / "one").contains("ranks"));
  EXPECT_EQ(summary["newton_iterations"], read_summary(folder / "one")["newton_iterations"]);
  // CG to 1e-12 on both: the total energies and largest stresses agree far below it.
  const std::vector<double> row_one = last_step_of_log(folder / "one"), row_two = last_step_of_log(folder / "two");
  ASSERT_EQ(row_one.size(), 8u);
  ASSERT_EQ(row_two.size(), 8u);
  EXPECT_NEAR(row_two[6], row_one[6], 1e-8 * std::abs(row_one[6]));
  EXPECT_NEAR(row_two[7], row_one[7], 1e-8 * std::abs(row_one[7]));
}

TEST(Ranks, BadInputOnEveryRankIsRankZerosOneLine) {
  SKIP_WITHOUT_MPI();
  const auto out = fresh_directory("two-ranks-bad") / "run";
  const auto result = run_altfem_on_ranks(2, {"run", source_path("scenes/cantilever.json").string(), "--method", "fem",
                                              "--set", "material/poisson_ratio=0.5", "--out", out.string()});
  EXPECT_EQ(result.exit_code, 2) << result.err;
  int altfem_lines = 0;
  for (const std::string& line : lines_of(result.err)) altfem_lines += line.rfind("altfem: error: ", 0) == 0;
  EXPECT_EQ(altfem_lines, 1) << result.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(Ranks, OnlyRunRunsOverSeveralProcesses) {
  SKIP_WITHOUT_MPI();
  const auto result = run_altfem_on_ranks(2, {"check", source_path("scenes/cantilever.json").string()});
  EXPECT_EQ(result.exit_code, 2) << result.err;
  EXPECT_NE(result.err.find("only `altfem run` runs over several processes"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace altfem::test
