// Per-element set-up cost of the polyhedral methods on one core: the harmonic basis of
// an element (MFS fit, Martin et al. 2008 §5), its tabulation with the consistency
// correction, both with the element stiffness (the paper's Table 1), and DG's exact
// element and face matrices (Kaufmann et al. 2009 §5), for a hex-like cell and a
// non-convex L-shaped prism. Medians on one core with
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

// Args: cell kind, MFS samples per edge (5: MfsOptions' and discretization.harmonic's default).
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

// What the paper's Table 1 times per polyhedral element (48–688 ms there): the basis, and
// the element's linear-elastic stiffness K_e (3n × 3n) integrated with it — here the whole
// per-element set-up of the harmonic method at its defaults (5 samples per edge, an
// order-2 rule, the consistency correction), then K_ab = Σ_q w_q (λ ∇N_a ∇N_bᵀ +
// μ ∇N_b ∇N_aᵀ + μ ∇N_a·∇N_b I). Arg: cell kind.
void harmonic_element_setup(benchmark::State& state) {
  const Polyhedron element = cell(static_cast<int>(state.range(0)));
  const double lambda = 1.5, mu = 1.0;
  const auto n = static_cast<int>(element.vertices.rows());
  Eigen::MatrixXd stiffness(3 * n, 3 * n);
  long long points = 0;
  for (auto _ : state) {
    const harmonic::ElementHarmonicBasis basis(element, {});
    const PolyhedronRule rule = polyhedron_rule(element, 2);
    const harmonic::HarmonicTabulation table = harmonic::tabulate_harmonic_element(basis, rule, true);
    stiffness.setZero();
    for (Eigen::Index q = 0; q < table.weights.size(); ++q)
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
          const Eigen::RowVector3d ga = table.gradients.row(q * n + a), gb = table.gradients.row(q * n + b);
          stiffness.block<3, 3>(3 * a, 3 * b) += table.weights[q] * (lambda * ga.transpose() * gb + mu * gb.transpose() * ga +
                                                                      mu * ga.dot(gb) * Eigen::Matrix3d::Identity());
        }
    benchmark::DoNotOptimize(stiffness.data());
    points = table.weights.size();
  }
  state.counters["points"] = static_cast<double>(points);
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
BENCHMARK(harmonic_element_setup)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(dg_element_matrices)->ArgsProduct({{0, 1}, {1, 2, 3}})->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
