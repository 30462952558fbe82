// Evaluating a scene expression (the manufactured body force of scenes/manufactured.json)
// at 100k points: one parser serially (VectorExpression::evaluate), chunks in parallel
// with a parser each (evaluate_at_points, what loads and field errors use), and point by
// point through the parser pool (operator(), what nodal and weak boundary data use).
#include <benchmark/benchmark.h>

#include "shared/simulation/field_quadrature.hpp"

namespace altfem {
namespace {

const VectorExpression& body_force() {
  static const VectorExpression force(
      {"pi*a*(lambda*(pi*sin(pi*x)*sin(pi*y)*sin(pi*z) - 2*x*cos(pi*z) - exp(x)*cos(pi*y)) + "
       "mu*(4*pi*sin(pi*x)*sin(pi*y)*sin(pi*z) - 2*x*cos(pi*z) - exp(x)*cos(pi*y)))",
       "a*(lambda*pi^2*(exp(x)*sin(pi*y) - cos(pi*x)*cos(pi*y)*sin(pi*z)) + mu*((2*pi^2 - 1)*exp(x)*sin(pi*y) - "
       "pi^2*cos(pi*x)*cos(pi*y)*sin(pi*z)))",
       "a*(lambda*pi^2*(x^2*sin(pi*z) - cos(pi*x)*sin(pi*y)*cos(pi*z)) + mu*((2*pi^2*x^2 - 2)*sin(pi*z) - "
       "pi^2*cos(pi*x)*sin(pi*y)*cos(pi*z)))"},
      {{"a", 0.01}, {"lambda", 15.0}, {"mu", 10.0}}, "bench", "/loads/body_force");
  return force;
}

const Eigen::MatrixXd& points() {
  static const Eigen::MatrixXd random = (Eigen::MatrixXd::Random(100000, 3).array() + 1) / 2;
  return random;
}

void serial_batch(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(body_force().evaluate(points(), 1.0));
  state.SetItemsProcessed(state.iterations() * points().rows());
}
BENCHMARK(serial_batch)->Unit(benchmark::kMillisecond)->UseRealTime();

void parallel_chunks(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(evaluate_at_points(body_force(), points(), 1.0));
  state.SetItemsProcessed(state.iterations() * points().rows());
}
BENCHMARK(parallel_chunks)->Unit(benchmark::kMillisecond)->UseRealTime();

void point_by_point(benchmark::State& state) {
  Eigen::MatrixXd values(points().rows(), 3);
  for (auto _ : state) {
    for (Eigen::Index p = 0; p < points().rows(); ++p)
      values.row(p) = body_force()(points().row(p).transpose(), 1.0).transpose();
    benchmark::DoNotOptimize(values.data());
  }
  state.SetItemsProcessed(state.iterations() * points().rows());
}
BENCHMARK(point_by_point)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace altfem

BENCHMARK_MAIN();
