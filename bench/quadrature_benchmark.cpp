// FCM quadrature (issue #16; Longva et al. 2020, §4.4–4.5, §6.3), medians printed:
//
//   bench_quadrature [--repetitions N] [--method lp|nnls|caratheodory] [--part cell|cylinder]
//
// (all three methods and both parts by default). Wall-clock medians are printed with the
// process's CPU time over the same runs: on a shared machine the ratio CPU / (wall ×
// threads) says how much of the machine the benchmark actually had.
//
// 1. Simplifying one Hex20 cut cell at m = 4 from about 3,000 intersection points, with
//    the LP (Clp) and the LP-free NNLS (Lawson–Hanson) and Carathéodory (recombination)
//    simplifiers, on one thread (target: <= 2 ms median each), with the moment
//    residuals, and the default's phases (moment matrix, recombination).
// 2. Whole-mesh generation + simplification for a hollow cylinder (length 16, radii
//    1 and 0.5) in a 7 × 7 × 56 Hex20 grid of cubes, ~2,000 cells meeting the object as
//    in §6.2–6.3, on all threads (target: <= 2 s on 2 cores), with point counts
//    (the paper: 5,857,880 -> 70,560).
#include <omp.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench/median.hpp"
#include "bench/process_usage.hpp"
#include "shared/cut_cells/cell_rules.hpp"
#include "shared/cut_cells/cut_cell_rule.hpp"
#include "shared/element/reference_element.hpp"
#include "shared/geometry/analytic_shape.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "shared/mesh/tetrahedralize.hpp"
#include "shared/quadrature/caratheodory_recombination.hpp"
#include "shared/quadrature/chebyshev_moment_matrix.hpp"

namespace {

using namespace altfem;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The intersection rule of the reference Hex20 cell with a tilted, finely gridded box
/// that covers about half of it: ~3,000 points at m = 4.
QuadratureRule hex20_cut_cell_rule() {
  const VolumeMesh box =
      structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d(0.2, -1.4, -1.4), Eigen::Vector3d(1.6, 1.4, 1.4)),
                      Eigen::Vector3i(1, 2, 2), ElementType::tet4);
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  std::vector<TetrahedronCorners> tetrahedra(box.cells.rows());
  for (Eigen::Index t = 0; t < box.cells.rows(); ++t)
    for (int c = 0; c < 4; ++c)
      tetrahedra[t].row(c) = (rotation * box.nodes.row(box.cells(t, c)).transpose()).transpose();
  const ReferenceElement& element = reference_element(ElementType::hex20);
  const CellGeometry cell(ElementType::hex20, element.nodes().topRows(8));
  return intersection_rule(cell, tetrahedra, 4).rule;
}

void simplify_one_cell(int repetitions, const std::vector<SimplificationMethod>& methods) {
  const QuadratureRule rule = hex20_cut_cell_rule();
  std::printf("one Hex20 cut cell, m = 4: %lld initial points\n", static_cast<long long>(rule.points.rows()));
  for (const SimplificationMethod method : methods) {
    std::vector<double> times;
    SimplificationResult result;
    for (int r = 0; r < repetitions; ++r) {
      const auto start = std::chrono::steady_clock::now();
      result = simplify_quadrature(rule, {4, method, 1e-12});
      times.push_back(seconds_since(start));
    }
    std::printf("  %-12s median %.3f ms, %lld points, residual %.2e%s\n",
                std::string(simplification_method_name(method)).c_str(), 1e3 * bench::median(times),
                static_cast<long long>(result.rule.points.rows()), result.residual, result.failed ? " FAILED" : "");
  }
  // The default's two large phases on their own; the rest of simplify_quadrature is the
  // re-solve on the chosen points and the residual.
  std::vector<double> moment_times, recombination_times;
  for (int r = 0; r < repetitions; ++r) {
    auto start = std::chrono::steady_clock::now();
    const Eigen::MatrixXd moments = chebyshev_moment_matrix(rule.points, 4);
    moment_times.push_back(seconds_since(start));
    start = std::chrono::steady_clock::now();
    const Eigen::VectorXd weights = caratheodory_recombination(moments, rule.weights, moments.rows());
    recombination_times.push_back(seconds_since(start));
  }
  std::printf("  phases: Chebyshev moment matrix median %.3f ms, recombination median %.3f ms\n",
              1e3 * bench::median(moment_times), 1e3 * bench::median(recombination_times));
}

void hollow_cylinder(int repetitions, const std::vector<SimplificationMethod>& methods) {
  const auto shape = make_cylinder(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 16.0, 1.0, 0.5);
  const double cell_size = 2.0 / 7.0;
  const Eigen::AlignedBox3d box(Eigen::Vector3d(-1, -1, 0), Eigen::Vector3d(1, 1, 16));
  const VolumeMesh grid = structured_grid(box, Eigen::Vector3i(7, 7, 56), ElementType::hex20);
  auto start = std::chrono::steady_clock::now();
  const VolumeMesh embedded = tetrahedralize_shape(*shape, cell_size);
  std::printf("hollow cylinder: %lld embedded tetrahedra (Mesh_3, %.2f s, not counted), %d threads\n",
              static_cast<long long>(embedded.cells.rows()), seconds_since(start), omp_get_max_threads());
  for (const SimplificationMethod method : methods) {
    std::vector<double> generation, total, total_cpu;
    CellRules rules;
    const double cpu_start = bench::process_cpu_seconds();
    for (int r = 0; r < repetitions; ++r) {
      start = std::chrono::steady_clock::now();
      rules = compute_cell_rules(grid, embedded, {4, false});
      generation.push_back(seconds_since(start));
      start = std::chrono::steady_clock::now();
      const double run_cpu_start = bench::process_cpu_seconds();
      rules = compute_cell_rules(grid, embedded, {4, true, method});
      total.push_back(seconds_since(start));
      total_cpu.push_back(bench::process_cpu_seconds() - run_cpu_start);
    }
    double wall = 0.0;
    for (int r = 0; r < repetitions; ++r) wall += generation[r] + total[r];
    const double cpu_share = (bench::process_cpu_seconds() - cpu_start) / (wall * omp_get_max_threads());
    std::printf(
        "  %-12s %d cut + %d inside cells; %lld -> %lld points; %d kept unsimplified; max residual %.2e\n"
        "       median generation only %.3f s, generation + simplification %.3f s (CPU share %.0f%%;\n"
        "       CPU time of generation + simplification, all threads: median %.3f s)\n",
        std::string(simplification_method_name(method)).c_str(), rules.cut_cells, rules.inside_cells,
        static_cast<long long>(rules.initial_points), static_cast<long long>(rules.final_points),
        rules.failed_simplifications, rules.max_residual, bench::median(generation), bench::median(total),
        100.0 * cpu_share, bench::median(total_cpu));
  }
}

}  // namespace

int main(int argc, char** argv) {
  int repetitions = 5;
  const std::vector<SimplificationMethod> all_methods = {SimplificationMethod::linear_program,
                                                         SimplificationMethod::nonnegative_least_squares,
                                                         SimplificationMethod::caratheodory};
  std::vector<SimplificationMethod> methods = all_methods;
  std::string part;
  for (int i = 1; i < argc; i += 2) {
    const std::string key = argv[i], value = i + 1 < argc ? argv[i + 1] : "";
    if (key == "--repetitions") {
      repetitions = std::max(1, std::atoi(value.c_str()));
    } else if (key == "--method") {
      const auto named = std::find_if(all_methods.begin(), all_methods.end(),
                                      [&](SimplificationMethod m) { return simplification_method_name(m) == value; });
      if (named == all_methods.end()) {
        std::fprintf(stderr, "bench_quadrature: --method %s: expected lp, nnls or caratheodory\n", value.c_str());
        return 2;
      }
      methods = {*named};
    } else if (key == "--part" && (value == "cell" || value == "cylinder")) {
      part = value;
    } else {
      std::fprintf(stderr,
                   "bench_quadrature: unknown option %s %s (expected --repetitions N, --method "
                   "lp|nnls|caratheodory, --part cell|cylinder)\n",
                   key.c_str(), value.c_str());
      return 2;
    }
  }
  if (part != "cylinder") {
    omp_set_num_threads(1);
    simplify_one_cell(10 * repetitions, methods);
  }
  if (part != "cell") {
    omp_set_num_threads(omp_get_num_procs());
    hollow_cylinder(repetitions, methods);
  }
  return 0;
}
