// Hexahedral slicing into polyhedral meshes (issue #15): the bunny (data/, 3.7k
// triangles) at 16³ and 32³ cells, the armadillo (data/, 100k triangles) at 32³, and a
// finely triangulated sphere (36k triangles) at 64³, uniform and octree-graded with 3
// levels; on all threads. Prints per case the median time of N runs (default 5), the cells
// by kind and cut pieces per second.
//
//   bench_slicing [--repetitions N]
//
// Target (issue #15): the bunny at 32³ in <= 2 s on 2 cores.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "bench/median.hpp"
#include "shared/mesh/slice_into_polyhedra.hpp"
#include "tests/unit/surfaces.hpp"

namespace {

using namespace altfem;

void run_case(const char* name, const SurfaceMesh& surface, int resolution, int octree_levels, int repetitions) {
  SlicingOptions options;
  options.resolution = resolution;
  options.octree_levels = octree_levels;
  std::vector<double> seconds;
  SlicedMesh sliced;
  for (int repetition = 0; repetition < repetitions; ++repetition) {
    const auto start = std::chrono::steady_clock::now();
    sliced = slice_into_polyhedra(surface, options);
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  const double time = bench::median(seconds);
  std::printf(
      "%-9s %3d^3 octree %d  median %8.4f s  cells %7d (grid hexahedra %6d, cut pieces %6d, split grid "
      "cells %4d, merged slivers %4d, octree cells %5d)  %9.0f cut pieces/s\n",
      name, resolution, octree_levels, time, sliced.mesh.cell_count(), sliced.hexahedra, sliced.cut_pieces,
      sliced.split_grid_cells, sliced.merged_slivers, sliced.coarse_cells, sliced.cut_pieces / time);
}

}  // namespace

int main(int argc, char** argv) {
  int repetitions = 5;
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--repetitions") == 0 && i + 1 < argc) repetitions = std::atoi(argv[++i]);
  const SurfaceMesh bunny = read_surface(std::string(ALTFEM_SOURCE_DIR) + "/data/surface/bunny_npm.off");
  run_case("bunny", bunny, 16, 0, repetitions);
  run_case("bunny", bunny, 32, 0, repetitions);
  const SurfaceMesh armadillo = read_surface(std::string(ALTFEM_SOURCE_DIR) + "/data/surface/armadillo.off");
  run_case("armadillo", armadillo, 32, 0, repetitions);
  // Slightly off the origin, so grid planes do not meet its poles.
  const SurfaceMesh sphere = test::sphere(1.0, 96, 192, Eigen::Vector3d(0.0123, -0.0311, 0.0071));
  run_case("sphere", sphere, 64, 0, repetitions);
  run_case("sphere", sphere, 64, 3, repetitions);
  return 0;
}
