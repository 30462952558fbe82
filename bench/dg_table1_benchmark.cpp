// Kaufmann et al. 2009 Table 1 (issue #18): DG on a 10 × 10 × 10 hexahedral grid of the
// unit cube, clamped weakly at x = 0 under a uniform body force, linear elasticity
// (E = 1, ν = 0.3), η = 20 (Kaufmann's convention), one thread. Phases per row:
// exact integration + assembly (DgLinearSystem: element and face matrices from moments,
// sparse K) and solve, three ways: CHOLMOD (analysis + factorisation + solve); PCG to a
// relative residual of 1e-8 preconditioned by the two-level cycle (block Jacobi smoother,
// vertex coarse space factorised exactly; Dobrev et al. 2006); and by the multilevel cycle
// (the same, its coarse solve a V-cycle over background grids, dg/grid_coarse_levels.hpp).
// The PCG solves include their set-up: coarse spaces, smoothers, Galerkin products PᵀKP,
// coarse factorisations. Prints medians, the PCG solutions' distance to the direct one, and
// the direct solve's analysis and factorisation apart, with the factor's flops, and the size
// of the two-level cycle's coarse factor.
//
//   bench_dg_table1 [--repetitions N] [--row "BZ k=1"]     (default 5, every row)
//
// The paper (Core 2 Duo 2.4 GHz, ms, integration + assembly + solve):
//   BZ k=1 12k DOFs 532 + 22 + 656; IP k=1 1,437 + 87 + 734;
//   BZ k=2 30k DOFs 3,062 + 152 + 7,797; IP k=2 8,344 + 621 + 8,484.
// Target: every row ≤ 1/15 of the paper's total, integration + assembly under the solve.
#include <omp.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "bench/dg_table1_problem.hpp"
#include "bench/median.hpp"
#include "dg/dg_discretization.hpp"
#include "dg/dg_linear_system.hpp"
#include "dg/grid_coarse_levels.hpp"
#include "dg/vertex_coarse_space.hpp"
#include "shared/solve/blas_threads.hpp"
#include "shared/solve/conjugate_gradient.hpp"
#include "shared/solve/linear_solver.hpp"
#include "shared/solve/two_level_preconditioner.hpp"

namespace {

using namespace altfem;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The phases of one PCG solve, ms: set-up (coarse spaces and the preconditioner's compute(),
// of which `galerkin` the top level's PᵀKP), iterations, and the two together.
struct PcgTimes {
  std::vector<double> setup, galerkin, iterations, total;
};

// The element blocks of block Jacobi: cell c's DOFs.
std::vector<std::vector<int>> element_blocks(const dg::DgLinearSystem& system) {
  std::vector<std::vector<int>> blocks(system.cell_count());
  for (int cell = 0; cell < system.cell_count(); ++cell)
    for (int dof = 3 * system.offset(cell); dof < 3 * system.offset(cell + 1); ++dof) blocks[cell].push_back(dof);
  return blocks;
}

struct Row {
  const char* name;
  dg::Flux flux;
  int degree;
  double paper_ms;  // the paper's integration + assembly + solve
};

enum class Cycle { two_level, multilevel };

}  // namespace

int main(int argc, char** argv) {
  int repetitions = 5;
  std::string only_row;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--repetitions") == 0 && i + 1 < argc) repetitions = std::atoi(argv[++i]);
    if (std::strcmp(argv[i], "--row") == 0 && i + 1 < argc) only_row = argv[++i];
  }
  omp_set_num_threads(1);  // the paper's timings are single-core: OpenMP's and
  set_blas_threads(1);     // OpenBLAS's threads (CHOLMOD's supernodal BLAS calls) alike

  const bench::DgTable1Problem problem = bench::dg_table1_problem();
  const PolyhedralMesh& mesh = problem.mesh;
  const std::vector<Polyhedron>& cells = problem.cells;
  const std::vector<dg::DgFace>& faces = problem.faces;
  const double youngs_modulus = problem.youngs_modulus, lambda = problem.lambda, mu = problem.mu;

  const Row rows[] = {{"BZ k=1", dg::Flux::babuska_zlamal, 1, 532 + 22 + 656},
                      {"IP k=1", dg::Flux::interior_penalty, 1, 1437 + 87 + 734},
                      {"BZ k=2", dg::Flux::babuska_zlamal, 2, 3062 + 152 + 7797},
                      {"IP k=2", dg::Flux::interior_penalty, 2, 8344 + 621 + 8484}};
  const Cycle cycles[] = {Cycle::two_level, Cycle::multilevel};
  const char* cycle_names[] = {"two-level", "multilevel"};
  std::printf("Kaufmann et al. 2009 Table 1, 10x10x10 hexahedra, 1 thread, medians of %d (ms)\n", repetitions);
  std::printf("%-8s %6s %10s %8s %8s %6s | %-10s %5s %7s %6s %8s %8s %9s %8s %7s\n", "row", "DOFs", "int+assem",
              "direct", "total", "speed", "PCG", "iter", "set-up", "PtKP", "iterate", "solve", "|du|/|u|", "total",
              "speed");
  for (const Row& row : rows) {
    if (!only_row.empty() && only_row != row.name) continue;
    std::vector<double> build_ms, direct_ms, analysis_ms, factorisation_ms;
    double factorisation_flops = 0;
    LinearSolverStatistics two_level_coarse;  // the two-level cycle's vertex-level factor
    PcgTimes pcg[2];
    int iterations[2] = {0, 0}, dofs = 0;
    double difference[2] = {0, 0};
    for (int r = 0; r < repetitions; ++r) {
      auto start = std::chrono::steady_clock::now();
      const dg::DgLinearSystem system(cells, faces, {row.degree, row.flux, 20 * youngs_modulus, lambda, mu});
      build_ms.push_back(1e3 * seconds_since(start));
      dofs = system.dof_count();
      const Eigen::VectorXd load = system.body_load([](const Eigen::Vector3d&) { return Eigen::Vector3d(0, 0, -1); });
      start = std::chrono::steady_clock::now();
      const auto solver = make_linear_solver({});
      solver->factorize(system.stiffness());
      Eigen::VectorXd direct(load.size());
      solver->solve(load, direct);
      direct_ms.push_back(1e3 * seconds_since(start));
      analysis_ms.push_back(1e3 * solver->statistics().analysis_seconds);
      factorisation_ms.push_back(1e3 * solver->statistics().factorisation_seconds);
      factorisation_flops = solver->statistics().factorisation_flops;

      for (int c = 0; c < 2; ++c) {
        start = std::chrono::steady_clock::now();
        dg::VertexCoarseSpace space = dg::vertex_coarse_space(mesh, system);
        const PreconditionerFactory factory =
            cycles[c] == Cycle::two_level ? dg::two_level_factory(element_blocks(system), std::move(space.prolongation))
                                          : dg::multilevel_factory(element_blocks(system), space.prolongation,
                                                                   dg::grid_coarse_levels(mesh, system, space));
        const std::unique_ptr<Preconditioner> preconditioner = factory();
        preconditioner->compute(system.stiffness());
        pcg[c].setup.push_back(1e3 * seconds_since(start));
        const auto& top = static_cast<const TwoLevelPreconditioner&>(*preconditioner);
        pcg[c].galerkin.push_back(1e3 * top.galerkin_seconds());
        if (cycles[c] == Cycle::two_level) two_level_coarse = top.coarse_statistics();
        const auto iterate = std::chrono::steady_clock::now();
        Eigen::VectorXd u = Eigen::VectorXd::Zero(load.size());
        ConjugateGradientWorkspace workspace;
        iterations[c] =
            conjugate_gradient(system.stiffness(), *preconditioner, load, u, {1e-8, 10000}, workspace).iterations;
        pcg[c].iterations.push_back(1e3 * seconds_since(iterate));
        pcg[c].total.push_back(1e3 * seconds_since(start));
        difference[c] = (u - direct).norm() / direct.norm();
      }
    }
    const double build = bench::median(build_ms), direct = bench::median(direct_ms);
    for (int c = 0; c < 2; ++c) {
      const double solve = bench::median(pcg[c].total);
      std::printf("%-8s %6d %10.1f %8.1f %8.1f %5.1fx | %-10s %5d %7.1f %6.1f %8.1f %8.1f %9.1e %8.1f %6.1fx\n",
                  row.name, dofs, build, direct, build + direct, row.paper_ms / (build + direct), cycle_names[c],
                  iterations[c], bench::median(pcg[c].setup), bench::median(pcg[c].galerkin),
                  bench::median(pcg[c].iterations), solve, difference[c], build + solve,
                  row.paper_ms / (build + solve));
    }
    const double factorisation = bench::median(factorisation_ms);
    std::printf("%-8s direct: analysis %.1f ms, factorisation %.1f ms (%.2f GFlop, %.1f GFlop/s)\n", row.name,
                bench::median(analysis_ms), factorisation, 1e-9 * factorisation_flops,
                1e-6 * factorisation_flops / factorisation);
    std::printf("%-8s two-level: its vertex-level factor has %.2fM entries, %.2f GFlop\n", row.name,
                1e-6 * two_level_coarse.factor_entries, 1e-9 * two_level_coarse.factorisation_flops);
  }
  return 0;
}
