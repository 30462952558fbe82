// The BLAS threads each phase of a direct solve gets (blas_thread_choice.hpp): one for
// small factorisations and for the triangular solves, never more than the free cores.
#include "shared/solve/blas_thread_choice.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>
#include <vector>

#include "shared/solve/linear_solver.hpp"
#include "tests/unit/solve/test_matrices.hpp"

namespace altfem {
namespace {

TEST(BlasThreadChoice, SmallFactorisationsRunOnOneThread) {
  EXPECT_EQ(factorisation_blas_threads(0.99 * minimum_flops_for_blas_threads, 16, 16, 0), 1);
  EXPECT_EQ(factorisation_blas_threads(minimum_flops_for_blas_threads, 16, 16, 0), 16);
}

TEST(BlasThreadChoice, LargeFactorisationsGetTheFreeCoresUpToTheLimit) {
  const double large = 1e3 * minimum_flops_for_blas_threads;
  EXPECT_EQ(factorisation_blas_threads(large, 2, 2, 0), 2);
  EXPECT_EQ(factorisation_blas_threads(large, 2, 2, 1), 1);   // one busy process beside the run
  EXPECT_EQ(factorisation_blas_threads(large, 2, 2, 7), 1);   // never fewer than one
  EXPECT_EQ(factorisation_blas_threads(large, 4, 2, 0), 2);   // OMP_NUM_THREADS=4 on 2 cores
  EXPECT_EQ(factorisation_blas_threads(large, 8, 16, 3), 8);  // the limit, however many are free
  EXPECT_EQ(factorisation_blas_threads(large, 16, 16, 3), 13);
}

TEST(BlasThreadChoice, ReadsTheRunnableCountOfLoadavg) {
  EXPECT_EQ(runnable_threads_in_loadavg("1.99 1.90 2.27 4/89 12892\n"), 4);
  EXPECT_EQ(runnable_threads_in_loadavg("0.00 0.01 0.05 1/123 4567"), 1);
  EXPECT_FALSE(runnable_threads_in_loadavg("").has_value());
  EXPECT_FALSE(runnable_threads_in_loadavg("1.99 1.90 2.27 4 89").has_value());
}

TEST(BlasThreadChoice, ReadsTheStateAfterTheLastParenthesisOfAThreadStat) {
  EXPECT_TRUE(thread_stat_is_runnable("4242 (altfem) R 1 4242 4242 0 -1"));
  EXPECT_FALSE(thread_stat_is_runnable("4242 (altfem) S 1 4242 4242 0 -1"));
  // A command may contain ") R": only the last ')' ends it.
  EXPECT_FALSE(thread_stat_is_runnable("4242 (a) R (b) S 1 4242"));
  EXPECT_FALSE(thread_stat_is_runnable("4242 (altfem)"));
}

// Two child processes spinning are two runnable threads elsewhere, whatever else the
// machine runs (other tests only add to the count); this process's own threads are not.
TEST(BlasThreadChoice, CountsBusyProcessesBesideThisOne) {
  std::vector<pid_t> children;
  for (int child = 0; child < 2; ++child) {
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0)
      for (;;) {
      }
    children.push_back(pid);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  int most = 0;
  for (int sample = 0; sample < 5; ++sample) most = std::max(most, runnable_threads_elsewhere());
  for (const pid_t pid : children) {
    kill(pid, SIGKILL);
    waitpid(pid, nullptr, 0);
  }
  EXPECT_GE(most, 2);
}

TEST(BlasThreadChoice, CholmodRecordsTheThreadsOfItsFactorisations) {
  const Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(4);
  auto solver = make_linear_solver({});
  solver->factorize(matrix);
  ASSERT_LT(solver->statistics().factorisation_flops, minimum_flops_for_blas_threads);
  EXPECT_EQ(solver->statistics().fewest_blas_threads, 1);
  EXPECT_EQ(solver->statistics().most_blas_threads, 1);
}

}  // namespace
}  // namespace altfem
