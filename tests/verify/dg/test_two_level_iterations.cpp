// The two-level preconditioner of Dobrev, Lazarov, Vassilevski & Zikatanov 2006 (their
// Theorem: with the continuous piecewise-linear coarse space and a block Jacobi/Gauss–Seidel
// smoother, κ(M⁻¹A) is bounded independently of h) on IP-DG linear elasticity: PCG's
// iterations to a relative residual of 1e-8 stay bounded as a hexahedral grid and a sliced
// sphere are refined, while block Jacobi alone needs about twice as many per halving of h
// (κ ~ h⁻²). The multilevel cycle (its coarse solve a V-cycle over background grids,
// dg/grid_coarse_levels.hpp) keeps them bounded too. Prints the tables.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "dg/dg_discretization.hpp"
#include "dg/grid_coarse_levels.hpp"
#include "dg/polyhedral_mesh_faces.hpp"
#include "dg/vertex_coarse_space.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"
#include "shared/mesh/slice_into_polyhedra.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "shared/solve/conjugate_gradient.hpp"
#include "tests/unit/surfaces.hpp"

namespace altfem::dg {
namespace {

struct Iterations {
  int dofs, block_jacobi, two_level, multilevel;
  int grid_levels;  // of the multilevel cycle: 0 when the vertex space is already its coarsest level
};

// PCG iterations for K u = f, f a unit body force, the mesh clamped weakly on its boundary
// faces below x = x_clamp (E = 1, ν = 0.3, η = 20, IP), with each preconditioner.
Iterations pcg_iterations(const PolyhedralMesh& mesh, int degree, double x_clamp, bool with_block_jacobi) {
  std::vector<DgFace> faces = mesh_faces(mesh);
  for (DgFace& face : faces)
    if (face.plus < 0 && face.polygon.col(0).maxCoeff() < x_clamp) face.condition = 0;
  const double lambda = 0.3 / (1.3 * 0.4), mu = 1 / 2.6;
  const DgLinearSystem system(mesh_cells(mesh), faces, {degree, Flux::interior_penalty, 20, lambda, mu});
  std::vector<std::vector<int>> blocks(system.cell_count());
  for (int cell = 0; cell < system.cell_count(); ++cell)
    for (int dof = 3 * system.offset(cell); dof < 3 * system.offset(cell + 1); ++dof) blocks[cell].push_back(dof);
  const Eigen::VectorXd load = system.body_load([](const Eigen::Vector3d&) { return Eigen::Vector3d(0.3, 0, -1); });
  const auto solve = [&](const PreconditionerFactory& factory) {
    const std::unique_ptr<Preconditioner> preconditioner = factory();
    preconditioner->compute(system.stiffness());
    Eigen::VectorXd u = Eigen::VectorXd::Zero(load.size());
    ConjugateGradientWorkspace workspace;
    return conjugate_gradient(system.stiffness(), *preconditioner, load, u, {1e-8, 5000}, workspace).iterations;
  };
  Iterations result{system.dof_count(), 0, 0, 0, 0};
  if (with_block_jacobi) result.block_jacobi = solve(block_jacobi_factory(blocks));
  const VertexCoarseSpace space = vertex_coarse_space(mesh, system);
  result.two_level = solve(two_level_factory(blocks, space.prolongation));
  std::vector<Eigen::SparseMatrix<double>> levels = grid_coarse_levels(mesh, system, space);
  result.grid_levels = static_cast<int>(levels.size());
  result.multilevel = solve(multilevel_factory(blocks, space.prolongation, std::move(levels)));
  return result;
}

void print_row(const char* mesh, int cells, const Iterations& iterations) {
  const std::string block_jacobi = iterations.block_jacobi > 0 ? std::to_string(iterations.block_jacobi) : "-";
  std::printf("  %-14s %7d %8d %14s %11d %11d (%d grid levels)\n", mesh, cells, iterations.dofs, block_jacobi.c_str(),
              iterations.two_level, iterations.multilevel, iterations.grid_levels);
}

TEST(TwoLevelIterations, StayBoundedUnderRefinementOfAHexahedralGrid) {
  std::printf("  %-14s %7s %8s %14s %11s %11s\n", "mesh", "cells", "DOFs", "block Jacobi", "two-level", "multilevel");
  for (int degree : {1, 2}) {
    std::vector<Iterations> rows;
    const std::vector<int> resolutions = degree == 1 ? std::vector<int>{4, 8, 16} : std::vector<int>{4, 8};
    for (int n : resolutions) {
      const PolyhedralMesh mesh = polyhedral_mesh_from_volume_mesh(structured_grid(
          Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()), {n, n, n}, ElementType::hex8));
      rows.push_back(pcg_iterations(mesh, degree, 1e-9, true));
      print_row(degree == 1 ? "grid, k = 1" : "grid, k = 2", n * n * n, rows.back());
    }
    for (size_t r = 1; r < rows.size(); ++r) {
      // κ(block Jacobi · K) ~ h⁻²: iterations ~ h⁻¹, about 2× per halving.
      EXPECT_GT(rows[r].block_jacobi, 1.6 * rows[r - 1].block_jacobi) << "k = " << degree;
      // Bounded: at most 25% more per halving of h (a constant, with PCG's mild start-up growth).
      EXPECT_LT(rows[r].two_level, 1.25 * rows[r - 1].two_level) << "k = " << degree;
      // The multilevel cycle is the two-level one while the vertex space is coarsest (4³):
      // bounded from the first grid with a grid level below its vertices on.
      if (rows[r - 1].grid_levels > 0) EXPECT_LT(rows[r].multilevel, 1.25 * rows[r - 1].multilevel) << "k = " << degree;
      else EXPECT_EQ(rows[r - 1].multilevel, rows[r - 1].two_level) << "k = " << degree;
    }
  }
}

TEST(TwoLevelIterations, StayBoundedUnderRefinementOfASlicedSphere) {
  // Cut cells: polyhedra with many vertices, some only on the cut surface.
  std::vector<Iterations> rows;
  for (int resolution : {4, 8, 12}) {
    SlicingOptions options;
    options.resolution = resolution;
    const SlicedMesh sliced =
        slice_into_polyhedra(test::sphere(0.8, 16, 32, Eigen::Vector3d(0.03, -0.02, 0.01)), options);
    rows.push_back(pcg_iterations(sliced.mesh, 1, -0.4, false));
    print_row("sphere, k = 1", sliced.mesh.cell_count(), rows.back());
  }
  // The coarsest slice is nearly all cut cells (5 iterations): bounded from the second on,
  // as on the grid (h shrinks by 1.5 here).
  EXPECT_LT(rows[2].two_level, 1.25 * rows[1].two_level);
  ASSERT_GT(rows[1].grid_levels, 0);
  EXPECT_LT(rows[2].multilevel, 1.25 * rows[1].multilevel);
}

}  // namespace
}  // namespace altfem::dg
