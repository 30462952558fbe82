// Per-element set-up cost of the polyhedral methods on one core: the harmonic basis of
// an element (MFS fit, Martin et al. 2008 §5) and its tabulation with the consistency
// correction, and DG's exact element and face matrices (Kaufmann et al. 2009 §5), for a
// hex-like cell and a non-convex L-shaped prism. Medians on one core with
//   OMP_NUM_THREADS=1 build-bench/bin/bench_polyhedral_element --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// (one thread: Eigen's products would otherwise spawn an OpenMP team per factorisation,
// which the method never does — it builds the bases inside a parallel loop over cells).
// Target (issue #19): basis + stiffness integration ≤ 2 ms per element.
#include <benchmark/benchmark.h>

#include "dg/exact_element_matrices.hpp"
#include "polyhedral/harmonic_tabulation.hpp"
#include "tests/unit/polyhedra.hpp"

namespace {

using namespace altfem;

Polyhedron cell(int kind) {
  return kind == 0 ? test::box(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 1.2, 0.9)) : test::l_prism();
}
const char* cell_name(int kind) { return kind == 0 ? "hexahedron" : "l_prism"; }

// Args: cell kind, MFS samples per edge (4: discretization.harmonic's default).
void harmonic_basis(benchmark::State& state) {
  const Polyhedron element = cell(static_cast<int>(state.range(0)));
  harmonic::MfsOptions options;
  options.edge_samples = static_cast<int>(state.range(1));
  for (auto _ : state) {
    harmonic::ElementHarmonicBasis basis(element, options);
    benchmark::DoNotOptimize(basis);
  }
  state.SetLabel(std::string(cell_name(static_cast<int>(state.range(0)))) + ", " + std::to_string(state.range(1)) +
                 " samples/edge");
}

void harmonic_tabulation(benchmark::State& state) {
  const Polyhedron element = cell(static_cast<int>(state.range(0)));
  const harmonic::ElementHarmonicBasis basis(element, {});
  const PolyhedronRule rule = polyhedron_rule(element, 2);
  for (auto _ : state) benchmark::DoNotOptimize(harmonic::tabulate_harmonic_element(basis, rule, true));
  state.counters["points"] = static_cast<double>(rule.weights.size());
  state.SetLabel(cell_name(static_cast<int>(state.range(0))));
}

void dg_element_matrices(benchmark::State& state) {
  const Polyhedron element = cell(static_cast<int>(state.range(0)));
  const dg::MonomialBasis basis(static_cast<int>(state.range(1)), Eigen::Vector3d(0.5, 0.6, 0.45), 1.8);
  for (auto _ : state) benchmark::DoNotOptimize(dg::exact_element_matrices(element, basis, 2.0, 1.5, 1000));
  state.SetLabel(std::string(cell_name(static_cast<int>(state.range(0)))) + ", degree " + std::to_string(state.range(1)));
}

BENCHMARK(harmonic_basis)->ArgsProduct({{0, 1}, {4, 5}})->Unit(benchmark::kMillisecond);
BENCHMARK(harmonic_tabulation)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(dg_element_matrices)->ArgsProduct({{0, 1}, {1, 2, 3}})->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
