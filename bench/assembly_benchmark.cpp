// Assembly throughput of ElasticAssembler (issue #9): Hessian, gradient and energy of a
// Stable Neo-Hookean cube, for Hex20 and Tet10 at the quadrature strength fem uses by
// default (2·degree = 4) and at Longva et al.'s (2020) Tet10 strength 3, with 1 and 2
// OpenMP threads. items_per_second is quadrature points per second (wall clock).
// points_per_cpu_s is quadrature points per second of process CPU time (all threads):
// on a shared, loaded machine the wall-clock rate of one thread understates the
// kernel, and this one does not; with 2 threads it shows the parallel overhead (equal to
// the 1-thread figure when the threads do no extra work).
//
//   bench_assembly --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//
// The face lines assemble FaceAssembler<JumpPenaltyKernel> (issue #14) over the faces of
// a 10³ grid of DG-like cells with their own basis functions (random traces): 2700 faces
// of 8 functions (two degree-1 monomial elements, 2×2 points per face) or of 20 (two
// degree-2 elements, 3×3 points); items_per_second is face quadrature points per second.
//
// `bench_assembly --callgrind-hessian ELEMENT STRENGTH ASSEMBLIES` skips the benchmarks
// and runs a fixed number of Hessian assemblies of a small mesh, for counting
// instructions per quadrature point under `valgrind --tool=callgrind` (scripts/bench).
#include <benchmark/benchmark.h>
#include <omp.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <tuple>

#include "bench/bench_problem.hpp"
#include "bench/process_usage.hpp"
#include "shared/assembly/face_assembler.hpp"
#include "shared/assembly/jump_penalty_kernel.hpp"
// The DG-like face grid of the face-assembler tests (random traces).
#include "tests/unit/assembly/face_fixture.hpp"

namespace {

using altfem::ElementType;
using altfem::bench::CubeProblem;
using altfem::bench::process_cpu_seconds;

struct Case {
  const char* name;
  ElementType type;
  int resolution;
  int strength;
};

// Hex20 12³ = 1728 cells; Tet10 8³·6 = 3072 cells: a few thousand elements each,
// large enough that the pattern (~10-50 MB) does not fit in cache, as in real runs.
constexpr Case cases[] = {
    {"hex20_12^3_strength4", ElementType::hex20, 12, 4},
    {"tet10_8^3_strength4", ElementType::tet10, 8, 4},
    {"tet10_8^3_strength3_longva", ElementType::tet10, 8, 3},
};

// Built once, in main before any benchmark runs: the assembler's per-thread scratch is
// sized by omp_get_max_threads() at construction, so it must exist before a benchmark
// lowers the thread count.
const CubeProblem& problem(const Case& c) {
  static std::map<std::tuple<ElementType, int, int>, std::unique_ptr<CubeProblem>> problems;
  auto& slot = problems[{c.type, c.resolution, c.strength}];
  if (!slot)
    slot = std::make_unique<CubeProblem>(c.type, c.resolution, c.strength, altfem::MaterialModel::stable_neo_hookean);
  return *slot;
}

enum class Kind { hessian, gradient, energy };

void run(benchmark::State& state, const Case& c, Kind kind, int threads) {
  const CubeProblem& p = problem(c);
  omp_set_num_threads(threads);
  const Eigen::VectorXd u = p.smooth_displacement();
  Eigen::SparseMatrix<double> hessian = p.assembler().pattern();
  Eigen::VectorXd gradient(p.dof_count());
  const double cpu_start = process_cpu_seconds();
  for (auto _ : state) {
    switch (kind) {
      case Kind::hessian: p.assembler().hessian(u, hessian); break;
      case Kind::gradient: p.assembler().gradient(u, gradient); break;
      case Kind::energy: benchmark::DoNotOptimize(p.assembler().energy(u)); break;
    }
    benchmark::ClobberMemory();
  }
  const double cpu_seconds = process_cpu_seconds() - cpu_start;
  state.SetItemsProcessed(state.iterations() * p.elements().point_count());
  state.counters["points_per_cpu_s"] =
      static_cast<double>(state.iterations() * p.elements().point_count()) / cpu_seconds;
  state.counters["points"] = static_cast<double>(p.elements().point_count());
  state.counters["dofs"] = p.dof_count();
  state.SetLabel(p.description());
}

struct FaceCase {
  const char* name;
  int cell_basis;
  int face_points;
};
constexpr FaceCase face_cases[] = {{"faces8_10^3_2x2points", 4, 4}, {"faces20_10^3_3x3points", 10, 9}};

struct FaceProblem {
  altfem::TabulatedFaces faces;
  altfem::TabulatedElements no_elements;
  altfem::BlockSparsity sparsity;
  altfem::FaceAssembler<altfem::JumpPenaltyKernel> assembler;

  explicit FaceProblem(const FaceCase& c)
      : faces(altfem::test::grid_faces(10, std::vector<int>(1000, c.cell_basis), c.face_points, 1)),
        sparsity(no_elements, faces.basis_groups()),
        assembler(faces, altfem::JumpPenaltyKernel(std::vector<double>(static_cast<size_t>(faces.size()), 10.0))) {
    assembler.bind(sparsity, 0);
  }
};

// Built in main before any benchmark runs, like problem().
const FaceProblem& face_problem(const FaceCase& c) {
  static std::map<std::string, std::unique_ptr<FaceProblem>> problems;
  auto& slot = problems[c.name];
  if (!slot) slot = std::make_unique<FaceProblem>(c);
  return *slot;
}

void run_faces(benchmark::State& state, const FaceCase& c, Kind kind, int threads) {
  const FaceProblem& p = face_problem(c);
  omp_set_num_threads(threads);
  const auto dofs = p.sparsity.pattern().rows();
  const Eigen::VectorXd u = Eigen::VectorXd::LinSpaced(dofs, -0.1, 0.1);
  Eigen::SparseMatrix<double> hessian = p.sparsity.pattern();
  Eigen::VectorXd gradient = Eigen::VectorXd::Zero(dofs);
  for (auto _ : state) {
    // add_*: the sums grow across iterations, which costs the same as refilling.
    switch (kind) {
      case Kind::hessian: p.assembler.add_hessian(u, hessian); break;
      case Kind::gradient: p.assembler.add_gradient(u, gradient); break;
      case Kind::energy: benchmark::DoNotOptimize(p.assembler.energy(u)); break;
    }
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * p.faces.point_count());
  state.counters["points"] = static_cast<double>(p.faces.point_count());
  state.counters["dofs"] = static_cast<double>(dofs);
}

int callgrind_hessian(const char* element, int strength, int assemblies) {
  const auto type = altfem::element_type_from_name(element);
  if (!type) {
    std::fprintf(stderr, "bench_assembly: unknown element '%s'\n", element);
    return 2;
  }
  // Small meshes: callgrind runs ~50x slower than native.
  const int resolution = altfem::element_shape(*type) == altfem::ElementShape::hexahedron ? 4 : 3;
  const CubeProblem p(*type, resolution, strength, altfem::MaterialModel::stable_neo_hookean);
  const Eigen::VectorXd u = p.smooth_displacement();
  Eigen::SparseMatrix<double> hessian = p.assembler().pattern();
  for (int i = 0; i < assemblies; ++i) p.assembler().hessian(u, hessian);
  std::printf("%s: %d assemblies, quadrature_points_processed %lld\n", p.description().c_str(), assemblies,
              assemblies * p.elements().point_count());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 5 && std::strcmp(argv[1], "--callgrind-hessian") == 0)
    return callgrind_hessian(argv[2], std::atoi(argv[3]), std::atoi(argv[4]));

  const int max_threads = omp_get_max_threads();
  for (const Case& c : cases) problem(c);
  for (const Case& c : cases)
    for (auto [kind, kind_name] : {std::pair{Kind::hessian, "hessian"}, std::pair{Kind::gradient, "gradient"},
                                   std::pair{Kind::energy, "energy"}})
      for (int threads : {1, 2}) {
        if (threads > max_threads) continue;
        const std::string name = std::string(kind_name) + "/" + c.name + "/threads:" + std::to_string(threads);
        benchmark::RegisterBenchmark(name.c_str(),
                                     [c, kind, threads](benchmark::State& state) { run(state, c, kind, threads); })
            ->UseRealTime()
            ->Unit(benchmark::kMillisecond);
      }
  for (const FaceCase& c : face_cases) face_problem(c);
  for (const FaceCase& c : face_cases)
    for (auto [kind, kind_name] :
         {std::pair{Kind::hessian, "face_hessian"}, std::pair{Kind::gradient, "face_gradient"}})
      for (int threads : {1, 2}) {
        if (threads > max_threads) continue;
        const std::string name = std::string(kind_name) + "/" + c.name + "/threads:" + std::to_string(threads);
        benchmark::RegisterBenchmark(
            name.c_str(), [c, kind, threads](benchmark::State& state) { run_faces(state, c, kind, threads); })
            ->UseRealTime()
            ->Unit(benchmark::kMillisecond);
      }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
