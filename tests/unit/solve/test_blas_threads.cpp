// After a factorisation or solve the BLAS worker threads are stopped (parked), not
// left spinning next to the OpenMP assembly that follows (blas_threads.hpp).
#include "shared/solve/blas_info.hpp"
#include "shared/solve/blas_threads.hpp"
#include "shared/solve/linear_solver.hpp"
#include "tests/unit/solve/test_matrices.hpp"

#include <dlfcn.h>
#include <gtest/gtest.h>

namespace altfem {
namespace {

// OpenBLAS's flag "worker threads are running" (exported by its pthread build).
const volatile int* openblas_threads_running() {
  return static_cast<const volatile int*>(dlsym(RTLD_DEFAULT, "blas_server_avail"));
}

TEST(BlasThreads, NoBlasWorkerOutlivesAFactorisationOrSolve) {
  const BlasInfo blas = loaded_blas();
  const volatile int* running = openblas_threads_running();
  if (blas.implementation.rfind("OpenBLAS", 0) != 0 || blas.threads < 2 || running == nullptr)
    GTEST_SKIP() << "needs a multi-threaded OpenBLAS, found " << blas.implementation << " with " << blas.threads
                 << " thread(s)";
  // Large enough that the top separators' BLAS-3 calls run on several threads.
  const Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(16);
  const Eigen::VectorXd rhs = Eigen::VectorXd::Ones(matrix.rows());
  auto solver = make_linear_solver({});
  for (int round = 0; round < 2; ++round) {  // the second round re-creates the threads it needs
    solver->factorize((1.0 + round) * matrix);
    EXPECT_EQ(*running, 0) << "round " << round;
    Eigen::VectorXd solution;
    solver->solve(rhs, solution);
    EXPECT_EQ(*running, 0) << "round " << round;
    EXPECT_LT(((1.0 + round) * matrix * solution - rhs).norm(), 1e-10 * rhs.norm());
  }
}

}  // namespace
}  // namespace altfem
