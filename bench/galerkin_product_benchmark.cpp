// The Galerkin coarse matrix Pᵀ A P of dg's two-level preconditioner (issue #18) on the
// Kaufmann et al. 2009 Table 1 problem (bench/dg_table1_problem.hpp, as bench_dg_table1
// solves it): a 10 × 10 × 10 hexahedral grid of the unit cube clamped weakly at x = 0,
// Babuška–Zlámal flux, η = 20, E = 1, ν = 0.3, degree k = 1 (A: 12,000², 921,600 entries)
// and k = 2 (30,000², 5,760,000), P the vertex coarse space (3,993 columns). Each iteration
// forms the product both ways, Eigen's `restriction * (matrix * prolongation)` and
// galerkin_product, in the same memory state, and times the latter (manual time); the
// counters are the medians of both over the run in ms, their ratio, and the relative
// Frobenius distance of the two results. Arguments: degree, threads. Medians with
//   bench_galerkin_product --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <omp.h>

#include <chrono>
#include <map>
#include <vector>

#include "bench/dg_table1_problem.hpp"
#include "bench/median.hpp"
#include "dg/dg_linear_system.hpp"
#include "dg/vertex_coarse_space.hpp"
#include "shared/solve/galerkin_product.hpp"

namespace {

using namespace altfem;

struct CoarseProblem {
  Eigen::SparseMatrix<double> matrix, prolongation, restriction;
};

const CoarseProblem& table1_problem(int degree) {
  static std::map<int, CoarseProblem> problems;
  auto [found, added] = problems.try_emplace(degree);
  if (!added) return found->second;
  const bench::DgTable1Problem scene = bench::dg_table1_problem();
  const dg::DgLinearSystem system(
      scene.cells, scene.faces, {degree, dg::Flux::babuska_zlamal, 20 * scene.youngs_modulus, scene.lambda, scene.mu});
  CoarseProblem& problem = found->second;
  problem.matrix = system.stiffness();
  problem.prolongation = dg::vertex_coarse_space(scene.mesh, system).prolongation;
  problem.restriction = problem.prolongation.transpose();
  return problem;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void BM_GalerkinProduct(benchmark::State& state) {
  const CoarseProblem& problem = table1_problem(static_cast<int>(state.range(0)));
  omp_set_num_threads(static_cast<int>(state.range(1)));
  std::vector<double> eigen_ms, galerkin_ms;
  double difference = 0;
  for (auto _ : state) {
    auto start = std::chrono::steady_clock::now();
    const Eigen::SparseMatrix<double> eigen = problem.restriction * (problem.matrix * problem.prolongation);
    eigen_ms.push_back(1e3 * seconds_since(start));
    benchmark::DoNotOptimize(eigen.valuePtr());
    start = std::chrono::steady_clock::now();
    const Eigen::SparseMatrix<double> ours =
        galerkin_product(problem.matrix, problem.prolongation, problem.restriction);
    const double seconds = seconds_since(start);
    state.SetIterationTime(seconds);
    galerkin_ms.push_back(1e3 * seconds);
    benchmark::DoNotOptimize(ours.valuePtr());
    if (galerkin_ms.size() == 1) difference = (ours - eigen).norm() / eigen.norm();
  }
  state.counters["eigen_ms"] = bench::median(eigen_ms);
  state.counters["galerkin_ms"] = bench::median(galerkin_ms);
  state.counters["eigen/galerkin"] = bench::median(eigen_ms) / bench::median(galerkin_ms);
  state.counters["difference"] = difference;
}
BENCHMARK(BM_GalerkinProduct)
    ->ArgNames({"degree", "threads"})
    ->Args({1, 1})
    ->Args({2, 1})
    ->Args({1, 2})
    ->Args({2, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime();

}  // namespace

BENCHMARK_MAIN();
