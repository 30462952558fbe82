// DG's exact integration and assembly (DgLinearSystem) on sliced scenes (issue #18, the
// integration phase of Table 1 beyond the plain grid): the bunny (data/) sliced at 16³
// and 32³ cells and a sphere at 32³, interior penalty, k = 1 and 2, one thread, with the
// matrices of translated cells and faces reused (dg/cell_similarity.hpp) and recomputed
// for every cell and face. Prints per case the median time of N runs (default 3), the
// cells and faces with the classes of translates among them.
//
//   bench_dg_sliced_integration [--repetitions N]
#include <omp.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "bench/median.hpp"
#include "dg/dg_linear_system.hpp"
#include "dg/polyhedral_mesh_faces.hpp"
#include "shared/mesh/slice_into_polyhedra.hpp"
#include "tests/unit/surfaces.hpp"

namespace {

using namespace altfem;

// Median milliseconds of building the system, and the last build's statistics.
std::pair<double, dg::SimilarityStatistics> time_system(const std::vector<Polyhedron>& cells,
                                                        const std::vector<dg::DgFace>& faces,
                                                        const dg::DgSettings& settings, int repetitions) {
  std::vector<double> milliseconds;
  dg::SimilarityStatistics statistics;
  for (int r = 0; r < repetitions; ++r) {
    const auto start = std::chrono::steady_clock::now();
    const dg::DgLinearSystem system(cells, faces, settings);
    milliseconds.push_back(1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    statistics = system.similarity();
  }
  return {bench::median(milliseconds), statistics};
}

void run_case(const char* name, const SurfaceMesh& surface, int resolution, int repetitions) {
  SlicingOptions options;
  options.resolution = resolution;
  const SlicedMesh sliced = slice_into_polyhedra(surface, options);
  const std::vector<Polyhedron> cells = dg::mesh_cells(sliced.mesh);
  std::vector<dg::DgFace> faces = dg::mesh_faces(sliced.mesh);
  for (dg::DgFace& face : faces)
    if (face.plus < 0) face.condition = 0;  // every boundary face carries a weak condition
  for (int degree : {1, 2}) {
    dg::DgSettings settings{degree, dg::Flux::interior_penalty, 20, 0.58, 0.38};
    const auto [reused, statistics] = time_system(cells, faces, settings, repetitions);
    settings.reuse_similar_cells = false;
    const double recomputed = time_system(cells, faces, settings, repetitions).first;
    std::printf("%-7s %3d^3 k=%d %7d cells %7d classes %8d faces %8d classes %12.1f %12.1f %8.1fx\n", name, resolution,
                degree, statistics.cells, statistics.cell_classes, statistics.faces, statistics.face_classes, reused,
                recomputed, recomputed / reused);
  }
}

}  // namespace

int main(int argc, char** argv) {
  int repetitions = 3;
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--repetitions") == 0 && i + 1 < argc) repetitions = std::atoi(argv[++i]);
  omp_set_num_threads(1);
  std::printf("DG integration + assembly on sliced meshes, interior penalty, 1 thread, medians of %d (ms)\n",
              repetitions);
  std::printf("%-7s %5s %3s %13s %15s %14s %16s %12s %12s %9s\n", "mesh", "grid", "k", "", "cell", "", "face", "reused",
              "recomputed", "speed-up");
  const SurfaceMesh bunny = read_surface(std::string(ALTFEM_SOURCE_DIR) + "/data/surface/bunny_npm.off");
  run_case("bunny", bunny, 16, repetitions);
  run_case("bunny", bunny, 32, repetitions);
  // Slightly off the origin, so grid planes do not meet its poles.
  run_case("sphere", test::sphere(1.0, 48, 96, Eigen::Vector3d(0.0123, -0.0311, 0.0071)), 32, repetitions);
  return 0;
}
