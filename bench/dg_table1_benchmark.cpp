// Kaufmann et al. 2009 Table 1 (issue #18): DG on a 10 × 10 × 10 hexahedral grid of the
// unit cube, clamped weakly at x = 0 under a uniform body force, linear elasticity
// (E = 1, ν = 0.3), η = 20 (Kaufmann's convention), one thread. Phases per row:
// exact integration + assembly (DgLinearSystem: element and face matrices from moments,
// sparse K) and solve (CHOLMOD analysis + factorisation + solve). Prints medians.
//
//   bench_dg_table1 [--repetitions N]     (default 5)
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
#include <vector>

#include "bench/median.hpp"
#include "dg/dg_linear_system.hpp"
#include "dg/polyhedral_mesh_faces.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "shared/solve/linear_solver.hpp"

namespace {

using namespace altfem;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Row {
  const char* name;
  dg::Flux flux;
  int degree;
  double paper_ms;  // the paper's integration + assembly + solve
};

}  // namespace

int main(int argc, char** argv) {
  int repetitions = 5;
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--repetitions") == 0 && i + 1 < argc) repetitions = std::atoi(argv[++i]);
  omp_set_num_threads(1);  // the paper's timings are single-core

  const VolumeMesh grid = structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()),
                                          {10, 10, 10}, ElementType::hex8);
  const PolyhedralMesh mesh = polyhedral_mesh_from_volume_mesh(grid);
  const std::vector<Polyhedron> cells = dg::mesh_cells(mesh);
  std::vector<dg::DgFace> faces = dg::mesh_faces(mesh);
  for (dg::DgFace& face : faces)
    if (face.plus < 0 && face.normal.x() < -0.5) face.condition = 0;  // the clamp at x = 0
  const double youngs_modulus = 1, poisson_ratio = 0.3;
  const double lambda = youngs_modulus * poisson_ratio / ((1 + poisson_ratio) * (1 - 2 * poisson_ratio));
  const double mu = youngs_modulus / (2 * (1 + poisson_ratio));

  const Row rows[] = {{"BZ k=1", dg::Flux::babuska_zlamal, 1, 532 + 22 + 656},
                      {"IP k=1", dg::Flux::interior_penalty, 1, 1437 + 87 + 734},
                      {"BZ k=2", dg::Flux::babuska_zlamal, 2, 3062 + 152 + 7797},
                      {"IP k=2", dg::Flux::interior_penalty, 2, 8344 + 621 + 8484}};
  std::printf("Kaufmann et al. 2009 Table 1, 10x10x10 hexahedra, 1 thread, medians of %d (ms)\n", repetitions);
  std::printf("%-8s %7s %22s %10s %10s %12s %10s %14s %12s\n", "row", "DOFs", "integration+assembly", "solve", "total",
              "paper total", "speed-up", "factor GFlop", "GFlop/s");
  for (const Row& row : rows) {
    std::vector<double> build_ms, solve_ms, factorisation_s;
    double flops = 0;
    int dofs = 0;
    for (int r = 0; r < repetitions; ++r) {
      auto start = std::chrono::steady_clock::now();
      const dg::DgLinearSystem system(cells, faces, {row.degree, row.flux, 20 * youngs_modulus, lambda, mu});
      build_ms.push_back(1e3 * seconds_since(start));
      dofs = system.dof_count();
      const Eigen::VectorXd load = system.body_load([](const Eigen::Vector3d&) { return Eigen::Vector3d(0, 0, -1); });
      start = std::chrono::steady_clock::now();
      const auto solver = make_linear_solver({});
      solver->factorize(system.stiffness());
      Eigen::VectorXd u(load.size());
      solver->solve(load, u);
      solve_ms.push_back(1e3 * seconds_since(start));
      factorisation_s.push_back(solver->statistics().factorisation_seconds);
      flops = solver->statistics().factorisation_flops;
    }
    const double build = bench::median(build_ms), solve = bench::median(solve_ms);
    // The factorisation's rate shows whether the solve runs at the speed of the BLAS.
    std::printf("%-8s %7d %22.1f %10.1f %10.1f %12.0f %9.1fx %14.2f %12.1f\n", row.name, dofs, build, solve,
                build + solve, row.paper_ms, row.paper_ms / (build + solve), 1e-9 * flops,
                1e-9 * flops / bench::median(factorisation_s));
  }
  return 0;
}
