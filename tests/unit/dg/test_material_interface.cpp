// DG with two materials (dg/dg_linear_system.hpp, DgCellMaterials): on the 4 × 4 × 4 grid
// of [0,1]³, cells left of x = ½ take MFEM example 17's λ = μ = 50 and the others
// λ = μ = 1. u = (f(x), 0, g(x)) with f, g piecewise affine, kinked at x = ½ so that the
// traction σ·e_x = ((λ+2μ) f', 0, μ g') is continuous there, solves div σ = 0: with the
// whole boundary's data imposed weakly, interior penalty of degree 1 reproduces it to
// round-off only if each side's stress in {σ} takes that side's λ, μ.
#include <gtest/gtest.h>

#include <Eigen/SparseLU>

#include "shared/common/eigen_decompositions.hpp"
#include "tests/unit/dg/hex_grid_cells.hpp"

namespace altfem::dg {
namespace {

constexpr double interface = 0.5;
const DgMaterial stiff{50, 50, 1, 20 * 150}, soft{1, 1, 1, 20 * 3};  // λ, μ, ρ, η = 20(λ + 2μ)

Eigen::Vector3d exact(const Eigen::Vector3d& x) {
  // f' = 1 and g' = 1 in the stiff part; (λ+2μ) f' and μ g' continuous across x = ½.
  const double normal_slope = (stiff.lambda + 2 * stiff.mu) / (soft.lambda + 2 * soft.mu),
               shear_slope = stiff.mu / soft.mu;
  if (x.x() <= interface) return {x.x(), 0, x.x()};
  const double beyond = x.x() - interface;
  return {interface + normal_slope * beyond, 0, interface + shear_slope * beyond};
}

DgCellMaterials two_materials(const std::vector<Polyhedron>& cells) {
  DgCellMaterials materials{{stiff, soft}, {}};
  for (const Polyhedron& cell : cells) materials.ids.push_back(cell.vertices.col(0).mean() < interface ? 0 : 1);
  return materials;
}

double relative_error(const DgCellMaterials& materials) {
  const test::GridCells grid = test::hex_grid_cells(4);
  const DgLinearSystem system(grid.cells, grid.faces, {1, Flux::interior_penalty}, materials);
  const Eigen::VectorXd load = system.dirichlet_load([](int, const Eigen::Vector3d& x) { return exact(x); });
  Eigen::SparseLU<Eigen::SparseMatrix<double>> solver(system.stiffness());
  const Eigen::VectorXd u = solver.solve(load);
  return system.l2_error(u, exact) / system.l2_error(Eigen::VectorXd::Zero(u.size()), exact);
}

TEST(DgMaterialInterface, InteriorPenaltyReproducesThePiecewiseAffineSolution) {
  const test::GridCells grid = test::hex_grid_cells(4);
  const double error = relative_error(two_materials(grid.cells));
  std::printf("  two materials, each side's own stress: relative L2 error %.3e\n", error);
  EXPECT_LT(error, 1e-10);
}

TEST(DgMaterialInterface, OneMaterialEverywhereDoesNotReproduceIt) {
  // The same data with the stiff material in every cell: the kinked field is no solution.
  const test::GridCells grid = test::hex_grid_cells(4);
  DgCellMaterials one = two_materials(grid.cells);
  std::fill(one.ids.begin(), one.ids.end(), 0);
  EXPECT_GT(relative_error(one), 1e-3);
}

TEST(DgMaterialInterface, MaterialIdsMustMatchTheCells) {
  const test::GridCells grid = test::hex_grid_cells(2);
  EXPECT_THROW(DgLinearSystem(grid.cells, grid.faces, {}, DgCellMaterials{{stiff}, {0, 0}}), std::invalid_argument);
  EXPECT_THROW(DgLinearSystem(grid.cells, grid.faces, {}, DgCellMaterials{{stiff}, std::vector<int>(8, 1)}),
               std::invalid_argument);
}

TEST(DgMaterialInterface, FacePenaltyTakesEachSidesEta) {
  // Eq. (20) with η inside the sum: an interior face of the 2³ grid (area ¼, volumes ⅛).
  const test::GridCells grid = test::hex_grid_cells(2);
  DgCellMaterials materials = two_materials(grid.cells);
  const DgLinearSystem system(grid.cells, grid.faces, {1, Flux::interior_penalty}, materials);
  for (const DgFace& face : system.faces()) {
    if (face.plus < 0 || face.normal.x() != 1.0) continue;  // the faces across x = ½
    EXPECT_NEAR(system.face_penalty(face).normal, 0.25 * (stiff.penalty + soft.penalty) / 0.125, 1e-9 * stiff.penalty);
  }
}

}  // namespace
}  // namespace altfem::dg
