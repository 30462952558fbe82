// CHOLMOD analysis + factorisation of the linear-elasticity stiffness of a unit cube
// clamped at x = 0 (issue #9), and for the large cube also PCG with incomplete Cholesky.
//
//   bench_factorisation [--repetitions N] [--large] [--large-element tet10|hex20]
//
// The ~30k-DOF Tet10 cube (target: analysis + factorisation <= 1.0 s on 2 cores) always
// runs, N times (default 5), and medians are printed. The ~300k-DOF cube (target:
// factorisation <= 60 s, peak RSS <= 6.5 GiB) runs once, only with --large or the
// environment variable ALTFEM_BENCH_LARGE=1: it takes minutes.
#include <omp.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "bench/bench_problem.hpp"
#include "bench/median.hpp"
#include "bench/process_usage.hpp"
#include "shared/common/error.hpp"
#include "shared/solve/blas_info.hpp"
#include "shared/solve/linear_solver.hpp"

namespace {

using altfem::ElementType;
using altfem::bench::ClampedSystem;
using altfem::bench::CubeProblem;
using altfem::bench::median;
using altfem::bench::peak_resident_gib;
using altfem::bench::process_cpu_seconds;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double relative_residual(const ClampedSystem& system, const Eigen::VectorXd& x) {
  return (system.matrix * x - system.rhs).norm() / system.rhs.norm();
}

// Linear material. The factorisation depends only on the matrix's pattern and values'
// conditioning, not on the rule, so the cheapest rule that is exact for the stiffness
// is used: strength 2 for straight Tet10 (∇N linear), fem's default 4 for Hex20 (whose
// 2×2×2 rule would leave zero-energy modes).
int stiffness_strength(ElementType type) { return type == ElementType::tet10 ? 2 : 4; }

ClampedSystem build(const CubeProblem& problem) {
  const auto start = std::chrono::steady_clock::now();
  ClampedSystem system = clamped_system(problem);
  const double seconds = seconds_since(start);
  std::printf("  geometry: unit cube [0,1]^3 clamped at x = 0, gravity load; %s\n", problem.description().c_str());
  std::printf("  matrix: %d free DOFs, %lld nonzeros (both triangles); assembled in %.3f s\n", system.free_dofs,
              static_cast<long long>(system.matrix.nonZeros()), seconds);
  return system;
}

void cholmod_case(const CubeProblem& problem, int repetitions, double target_seconds, bool target_includes_analysis) {
  const ClampedSystem system = build(problem);
  std::vector<double> analysis, factorisation, solve, sum, cpu;
  double residual = 0, factor_entries = 0, flops = 0;
  for (int r = 0; r < repetitions; ++r) {
    const auto solver = altfem::make_linear_solver({});
    Eigen::VectorXd x(system.rhs.size());
    const double cpu_start = process_cpu_seconds();
    solver->analyze(system.matrix);
    solver->factorize(system.matrix);
    cpu.push_back(process_cpu_seconds() - cpu_start);
    solver->solve(system.rhs, x);
    const altfem::LinearSolverStatistics& s = solver->statistics();
    analysis.push_back(s.analysis_seconds);
    factorisation.push_back(s.factorisation_seconds);
    solve.push_back(s.solve_seconds);
    sum.push_back(s.analysis_seconds + s.factorisation_seconds);
    residual = relative_residual(system, x);
    factor_entries = s.factor_entries;
    flops = s.factorisation_flops;
  }
  const double measured = target_includes_analysis ? median(sum) : median(factorisation);
  std::printf(
      "  CHOLMOD (median of %d, wall): analysis %.3f s, factorisation %.3f s, analysis+factorisation %.3f s, "
      "solve %.3f s; |Ax-b|/|b| = %.1e\n",
      repetitions, median(analysis), median(factorisation), median(sum), median(solve), residual);
  std::printf("  factor: %.2f M entries in L, %.2f GFLOP per factorisation, %.1f GFLOP/s\n", factor_entries / 1e6,
              flops / 1e9, flops / 1e9 / median(factorisation));
  std::printf(
      "  process CPU time of analysis+factorisation (all threads): %.3f s (wall/CPU %.2f: about 0.5-0.6 "
      "on 2 idle cores, above 1 on a loaded machine)\n",
      median(cpu), median(sum) / median(cpu));
  std::printf("  target: %s <= %.1f s: %s\n", target_includes_analysis ? "analysis+factorisation" : "factorisation",
              target_seconds, measured <= target_seconds ? "MET" : "MISSED");
  std::printf("  peak RSS so far: %.2f GiB\n", peak_resident_gib());
}

void pcg_case(const CubeProblem& problem) {
  const ClampedSystem system = build(problem);
  altfem::LinearSolverOptions options;
  options.kind = altfem::LinearSolverKind::pcg;
  options.preconditioner = "incomplete_cholesky";
  options.tolerance = 1e-8;
  options.max_iterations = 20000;
  const auto solver = altfem::make_linear_solver(options);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(system.rhs.size());
  std::string status = "converged";
  try {
    solver->factorize(system.matrix);
    solver->solve(system.rhs, x);
  } catch (const altfem::NumericalError& error) {
    status = std::string("FAILED: ") + error.what();
  }
  const altfem::LinearSolverStatistics& s = solver->statistics();
  std::printf(
      "  PCG + incomplete Cholesky (tolerance 1e-8, one run): set-up %.2f s, solve %.2f s, %ld iterations, "
      "|Ax-b|/|b| = %.1e, %s\n",
      s.factorisation_seconds, s.solve_seconds, s.iterations, relative_residual(system, x), status.c_str());
  std::printf("  peak RSS so far: %.2f GiB\n", peak_resident_gib());
}

}  // namespace

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // the large case takes minutes: show progress when piped
  int repetitions = 5;
  const char* large_env = std::getenv("ALTFEM_BENCH_LARGE");
  bool large = large_env != nullptr && std::strcmp(large_env, "1") == 0;
  ElementType large_element = ElementType::tet10;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--repetitions") == 0 && i + 1 < argc) {
      repetitions = std::max(1, std::atoi(argv[++i]));
    } else if (std::strcmp(argv[i], "--large") == 0) {
      large = true;
    } else if (std::strcmp(argv[i], "--large-element") == 0 && i + 1 < argc) {
      const auto type = altfem::element_type_from_name(argv[++i]);
      if (!type || (*type != ElementType::tet10 && *type != ElementType::hex20)) {
        std::fprintf(stderr, "bench_factorisation: --large-element: expected tet10 or hex20, got %s\n", argv[i]);
        return 2;
      }
      large_element = *type;
    } else {
      std::fprintf(stderr, "usage: bench_factorisation [--repetitions N] [--large] [--large-element tet10|hex20]\n");
      return 2;
    }
  }
  const altfem::BlasInfo blas = altfem::loaded_blas();
  std::printf("threads: %d OpenMP, %d BLAS; BLAS: %s\n", omp_get_max_threads(), blas.threads,
              blas.implementation.c_str());

  std::printf("\n[1] Tet10 cube, ~30k DOFs\n");
  {
    // (2·10 + 1)³ = 9261 nodes, 27,783 DOFs.
    const CubeProblem problem(ElementType::tet10, 10, stiffness_strength(ElementType::tet10),
                              altfem::MaterialModel::linear);
    cholmod_case(problem, repetitions, 1.0, true);
  }
  if (!large) {
    std::printf("\n[2] ~300k-DOF cube skipped (pass --large or set ALTFEM_BENCH_LARGE=1)\n");
    return 0;
  }
  // Tet10 23³: 47³ = 103,823 nodes, 311,469 DOFs; Hex20 28³: 95,033 nodes, 285,099 DOFs.
  const int resolution = large_element == ElementType::tet10 ? 23 : 28;
  std::printf("\n[2] %s cube, ~300k DOFs\n", std::string(altfem::element_name(large_element)).c_str());
  {
    const CubeProblem problem(large_element, resolution, stiffness_strength(large_element),
                              altfem::MaterialModel::linear);
    cholmod_case(problem, 1, 60.0, false);
    std::printf("  target: peak RSS <= 6.5 GiB: %s\n", peak_resident_gib() <= 6.5 ? "MET" : "MISSED");
    pcg_case(problem);
  }
  return 0;
}
