// Per-element set-up cost of the polyhedral methods on one core: the harmonic basis of
// an element (MFS fit, Martin et al. 2008 §5) and, separately, its stiffness integration
// (tabulation with the consistency correction at the order-2 rule, then K_e), both
// together (the paper's Table 1), and DG's exact element and face matrices (Kaufmann et
// al. 2009 §5). Cells: a hexahedron (8 nodes), an octree-coarse hexahedron with its
// finer neighbours' edge midpoints (20 nodes, octagonal faces), a non-convex L-shaped
// prism (12), and 40 cut cells of the bunny sliced at 16³ (each iteration takes the
// next cut cell, so the time is the mean over them); each of these fits its own face
// functions. harmonic_mesh_bases builds every cut cell of the bunny the way the method
// does, each face once, and reports the cost per element with the face fits amortised.
// Medians on one core with
//   OMP_NUM_THREADS=1 build/bin/bench_polyhedral_element --benchmark_repetitions=5
//   --benchmark_report_aggregates_only=true
// (configure with -DALTFEM_BENCHMARKS=ON; one thread: Eigen's products would otherwise
// spawn an OpenMP team per factorisation, which the method never does — it builds the
// bases inside a parallel loop over cells). Read the CPU column on a shared machine.
// Target (issue #19): basis and stiffness integration each ≤ 2 ms per element.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <ctime>
#include <map>

#include "dg/exact_element_matrices.hpp"
#include "polyhedral/harmonic_tabulation.hpp"
#include "polyhedral/mesh_face_coordinates.hpp"
#include "shared/mesh/slice_into_polyhedra.hpp"
#include "tests/unit/polyhedra.hpp"

namespace {

using namespace altfem;

enum CellKind { hexahedron, hexahedron20, l_prism, bunny_cut };

// The box with a node in the middle of each of its 12 edges: an octree cell whose
// neighbours are one level finer on every side (Martin et al. 2008, Fig. 4).
Polyhedron hexahedron_with_edge_nodes() {
  Polyhedron box = test::box(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 1.2, 0.9));
  std::map<std::pair<int, int>, int> midpoints;
  std::vector<Eigen::RowVector3d> vertices;
  for (Eigen::Index v = 0; v < box.vertices.rows(); ++v) vertices.push_back(box.vertices.row(v));
  for (auto& face : box.faces) {
    std::vector<int> loop;
    for (size_t k = 0; k < face.size(); ++k) {
      const int a = face[k], b = face[(k + 1) % face.size()];
      const auto [it, added] =
          midpoints.try_emplace({std::min(a, b), std::max(a, b)}, static_cast<int>(vertices.size()));
      if (added) vertices.push_back(0.5 * (box.vertices.row(a) + box.vertices.row(b)));
      loop.push_back(a);
      loop.push_back(it->second);
    }
    face = loop;
  }
  box.vertices.resize(static_cast<Eigen::Index>(vertices.size()), 3);
  for (size_t v = 0; v < vertices.size(); ++v) box.vertices.row(static_cast<Eigen::Index>(v)) = vertices[v];
  return box;
}

// The bunny sliced at 16³ (sliced once).
const PolyhedralMesh& bunny_mesh() {
  static const PolyhedralMesh mesh = [] {
    const SurfaceMesh bunny = read_surface(std::string(ALTFEM_SOURCE_DIR) + "/data/surface/bunny_npm.off");
    SlicingOptions options;
    options.resolution = 16;
    return slice_into_polyhedra(bunny, options).mesh;
  }();
  return mesh;
}

// 40 of its cut cells.
const std::vector<Polyhedron>& bunny_cut_cells() {
  static const std::vector<Polyhedron> cells = [] {
    const PolyhedralMesh& mesh = bunny_mesh();
    std::vector<int> cut;
    for (int cell = 0; cell < mesh.cell_count(); ++cell)
      if (mesh.cell_kinds[cell] != PolyhedralCellKind::hexahedron) cut.push_back(cell);
    // 40 of them, evenly spaced in cell order (all of them take minutes per benchmark).
    std::vector<Polyhedron> sample;
    for (size_t k = 0; k < 40 && k < cut.size(); ++k) sample.push_back(cell_polyhedron(mesh, cut[k * cut.size() / 40]));
    return sample;
  }();
  return cells;
}

// The cells a benchmark cycles through: one, or every bunny cut cell.
std::vector<Polyhedron> cells(int kind) {
  switch (kind) {
    case hexahedron: return {test::box(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 1.2, 0.9))};
    case hexahedron20: return {hexahedron_with_edge_nodes()};
    case l_prism: return {test::l_prism()};
    default: return bunny_cut_cells();
  }
}
std::string cell_name(int kind) {
  const char* names[] = {"hexahedron (8 nodes)", "octree hexahedron (20 nodes)", "l_prism (12 nodes)",
                         "bunny 16^3 cut cells"};
  std::string name = names[kind];
  if (kind == bunny_cut) {
    double nodes = 0;
    for (const Polyhedron& cell : bunny_cut_cells()) nodes += static_cast<double>(cell.vertices.rows());
    name += " (" + std::to_string(bunny_cut_cells().size()) + ", mean " +
            std::to_string(static_cast<int>(nodes / static_cast<double>(bunny_cut_cells().size()) + 0.5)) + " nodes)";
  }
  return name;
}

// K_ab = Σ_q w_q (λ ∇N_a ∇N_bᵀ + μ ∇N_b ∇N_aᵀ + μ ∇N_a·∇N_b I): the linear-elastic
// element stiffness (3n × 3n) from a tabulation.
void element_stiffness(const harmonic::HarmonicTabulation& table, int n, Eigen::MatrixXd& stiffness) {
  const double lambda = 1.5, mu = 1.0;
  stiffness.setZero(3 * n, 3 * n);
  for (Eigen::Index q = 0; q < table.weights.size(); ++q)
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) {
        const Eigen::RowVector3d ga = table.gradients.row(q * n + a), gb = table.gradients.row(q * n + b);
        stiffness.block<3, 3>(3 * a, 3 * b) +=
            table.weights[q] *
            (lambda * ga.transpose() * gb + mu * gb.transpose() * ga + mu * ga.dot(gb) * Eigen::Matrix3d::Identity());
      }
}

// Phase 1, the basis. Args: cell kind, MFS samples per edge (the 3–5 and 6; the
// default, 4, picked from these times against the accuracy tables, mfs_options.hpp).
void harmonic_basis(benchmark::State& state) {
  const std::vector<Polyhedron> elements = cells(static_cast<int>(state.range(0)));
  harmonic::MfsOptions options;
  options.edge_samples = static_cast<int>(state.range(1));
  size_t next = 0;
  for (auto _ : state) {
    harmonic::ElementHarmonicBasis basis(elements[next++ % elements.size()], options);
    benchmark::DoNotOptimize(basis);
  }
  state.SetLabel(cell_name(static_cast<int>(state.range(0))) + ", " + std::to_string(state.range(1)) + " samples/edge");
}

// Phase 2, the stiffness integration with a given basis: the order-2 rule of the
// polyhedron, the tabulation with the consistency correction, and K_e. Arg: cell kind.
void harmonic_stiffness(benchmark::State& state) {
  const std::vector<Polyhedron> elements = cells(static_cast<int>(state.range(0)));
  std::vector<harmonic::ElementHarmonicBasis> bases;
  for (const Polyhedron& element : elements) bases.emplace_back(element, harmonic::MfsOptions{});
  Eigen::MatrixXd stiffness;
  double points = 0;
  size_t next = 0;
  for (auto _ : state) {
    const size_t e = next++ % elements.size();
    const PolyhedronRule rule = polyhedron_rule(elements[e], 2);
    const harmonic::HarmonicTabulation table = harmonic::tabulate_harmonic_element(bases[e], rule, true);
    element_stiffness(table, static_cast<int>(elements[e].vertices.rows()), stiffness);
    benchmark::DoNotOptimize(stiffness.data());
    points += static_cast<double>(rule.weights.size());
  }
  state.counters["points"] = benchmark::Counter(points, benchmark::Counter::kAvgIterations);
  state.SetLabel(cell_name(static_cast<int>(state.range(0))));
}

// Both phases at the defaults: what the paper's Table 1 times per polyhedral element
// (48–688 ms there, Core 2 Duo 2.4 GHz). Arg: cell kind.
void harmonic_element_setup(benchmark::State& state) {
  const std::vector<Polyhedron> elements = cells(static_cast<int>(state.range(0)));
  Eigen::MatrixXd stiffness;
  double points = 0;
  size_t next = 0;
  for (auto _ : state) {
    const Polyhedron& element = elements[next++ % elements.size()];
    const harmonic::ElementHarmonicBasis basis(element, {});
    const PolyhedronRule rule = polyhedron_rule(element, 2);
    const harmonic::HarmonicTabulation table = harmonic::tabulate_harmonic_element(basis, rule, true);
    element_stiffness(table, static_cast<int>(element.vertices.rows()), stiffness);
    benchmark::DoNotOptimize(stiffness.data());
    points += static_cast<double>(rule.weights.size());
  }
  state.counters["points"] = benchmark::Counter(points, benchmark::Counter::kAvgIterations);
  state.SetLabel(cell_name(static_cast<int>(state.range(0))));
}

// Phase 1 over a whole mesh, as the method builds it: every face of the bunny's cut
// cells fitted once (shared by its two cells), then every cut cell's element fit on
// them. The honest per-element cost amortises the face fits: per_element = (all face
// fits + all element fits) / cells; per_face is one face fit. Arg: MFS samples per edge.
void harmonic_mesh_bases(benchmark::State& state) {
  const PolyhedralMesh& mesh = bunny_mesh();
  harmonic::MfsOptions options;
  options.edge_samples = static_cast<int>(state.range(0));
  std::vector<int> cut;
  for (int cell = 0; cell < mesh.cell_count(); ++cell)
    if (mesh.cell_kinds[cell] != PolyhedralCellKind::hexahedron) cut.push_back(cell);
  // Processor time, like the CPU column (one thread; the wall time of a shared machine
  // counts the neighbours' work too).
  const auto processor_seconds = [] { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; };
  double face_seconds = 0, cell_seconds = 0, faces = 0;
  for (auto _ : state) {
    const double start = processor_seconds();
    const auto coordinates = harmonic::mesh_face_coordinates(mesh, cut, options);
    const double middle = processor_seconds();
    for (int cell : cut) benchmark::DoNotOptimize(harmonic::cell_harmonic_basis(mesh, cell, coordinates, options));
    face_seconds += middle - start;
    cell_seconds += processor_seconds() - middle;
    faces = static_cast<double>(
        std::count_if(coordinates.begin(), coordinates.end(), [](const auto& face) { return face.has_value(); }));
  }
  const double iterations = static_cast<double>(state.iterations()), cells = static_cast<double>(cut.size());
  state.counters["cells"] = cells;
  state.counters["faces"] = faces;
  state.counters["per_element_ms"] = 1e3 * (face_seconds + cell_seconds) / iterations / cells;
  state.counters["element_fit_ms"] = 1e3 * cell_seconds / iterations / cells;
  state.counters["per_face_ms"] = 1e3 * face_seconds / iterations / faces;
  state.SetLabel("bunny 16^3, every cut cell, " + std::to_string(state.range(0)) + " samples/edge");
}

void dg_element_matrices(benchmark::State& state) {
  const Polyhedron element = cells(static_cast<int>(state.range(0))).front();
  const dg::MonomialBasis basis(static_cast<int>(state.range(1)), Eigen::Vector3d(0.5, 0.6, 0.45), 1.8);
  for (auto _ : state) benchmark::DoNotOptimize(dg::exact_element_matrices(element, basis, 2.0, 1.5, 1000));
  state.SetLabel(cell_name(static_cast<int>(state.range(0))) + ", degree " + std::to_string(state.range(1)));
}

BENCHMARK(harmonic_basis)
    ->ArgsProduct({{hexahedron, hexahedron20, l_prism, bunny_cut}, {3, 4, 5, 6}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(harmonic_mesh_bases)->Arg(harmonic::MfsOptions{}.edge_samples)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(harmonic_stiffness)->DenseRange(hexahedron, bunny_cut)->Unit(benchmark::kMillisecond);
BENCHMARK(harmonic_element_setup)->DenseRange(hexahedron, bunny_cut)->Unit(benchmark::kMillisecond);
BENCHMARK(dg_element_matrices)->ArgsProduct({{hexahedron, l_prism}, {1, 2, 3}})->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
