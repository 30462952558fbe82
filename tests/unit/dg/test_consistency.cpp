// Kaufmann et al. 2009, Fig. 1, in 3D: a linear elasticity problem whose exact solution
// is quadratic, on a 4 × 4 × 4 grid, with Dirichlet data on the whole boundary imposed
// weakly. Interior penalty with degree 2 is consistent: it reproduces the solution to
// round-off for any penalty large enough for stability. Babuška–Zlámal is not: its
// error shrinks only as the penalty grows. Prints the table.
#include <gtest/gtest.h>

#include <Eigen/SparseLU>
#include <cstdio>

#include "shared/common/eigen_decompositions.hpp"
#include "tests/unit/dg/hex_grid_cells.hpp"
#include "tests/unit/dg/lame_parameters.hpp"

namespace altfem::dg {
namespace {

// u = (x² + 2yz, xy − z², xz + y²): Δu = (2, −2, 2), ∇ div u = (4, 0, 0), so the body
// force f = −div σ = −μ Δu − (λ + μ) ∇ div u is constant.
Eigen::Vector3d exact(const Eigen::Vector3d& x) {
  return {x.x() * x.x() + 2 * x.y() * x.z(), x.x() * x.y() - x.z() * x.z(), x.x() * x.z() + x.y() * x.y()};
}
const Eigen::Vector3d body_force = -mu * Eigen::Vector3d(2, -2, 2) - (lambda + mu) * Eigen::Vector3d(4, 0, 0);

// max |u_h − u| over the coefficients, relative to max |u|.
double solve_and_compare(Flux flux, double penalty) {
  const test::GridCells grid = test::hex_grid_cells(4);
  const DgLinearSystem system(grid.cells, grid.faces, {2, flux, penalty, lambda, mu});
  const Eigen::VectorXd load = system.body_load([](const Eigen::Vector3d&) { return body_force; }) +
                               system.dirichlet_load([](int, const Eigen::Vector3d& x) { return exact(x); });
  Eigen::SparseLU<Eigen::SparseMatrix<double>> solver(system.stiffness());
  const Eigen::VectorXd u = solver.solve(load);
  const Eigen::VectorXd expected = system.interpolate(exact);
  return (u - expected).cwiseAbs().maxCoeff() / expected.cwiseAbs().maxCoeff();
}

TEST(ConsistencyFigure1, InteriorPenaltyReproducesAQuadraticSolutionBabuskaZlamalDoesNot) {
  std::printf("  %8s %14s %14s\n", "penalty", "IP error", "BZ error");
  double previous_bz = INFINITY;
  for (double penalty : {5.0, 20.0, 100.0}) {
    const double ip = solve_and_compare(Flux::interior_penalty, penalty);
    const double bz = solve_and_compare(Flux::babuska_zlamal, penalty);
    std::printf("  %8.0f %14.3e %14.3e\n", penalty, ip, bz);
    EXPECT_LT(ip, 1e-9);
    EXPECT_GT(bz, 1e-6);
    EXPECT_LT(bz, previous_bz);
    previous_bz = bz;
  }
}

}  // namespace
}  // namespace altfem::dg
