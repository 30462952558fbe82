// Example 4: why interior-penalty DG is consistent and Babuška–Zlámal is not
// (Kaufmann et al. 2009, §4 and Fig. 1, here in 3D).
//
//   build/bin/ex4_dg_exactness
//
// Linear elasticity −div σ(u) = f on the unit cube with u = g on its whole boundary,
// σ(u) = λ tr ε(u) I + 2μ ε(u), discretized with discontinuous polynomials of degree
// k = 2 on each cell of a 3 × 3 × 3 hexahedral grid. The exact solution below is
// quadratic, so it lies in the discrete space. Two ways to glue the cells (eqs. (19)–(26)):
//   interior penalty (IP): a(u,v) = Σ_K ∫_K σ(u):ε(v) − Σ_f ∫_f ({σ(u)}n·[v] + {σ(v)}n·[u])
//                          + Σ_f η_f ∫_f [u]·[v]
//     The face terms vanish for the exact solution (it has no jumps and its traction is
//     single-valued), so the exact solution satisfies the discrete equations: IP
//     reproduces it to round-off, whatever η (large enough for stability).
//   Babuška–Zlámal (BZ): a(u,v) = Σ_K ∫_K σ(u):ε(v) + Σ_f η_f ∫_f [u]·[v]
//     Without the traction terms the exact solution does NOT satisfy the discrete
//     equations (its traction on the faces is missing): the error is O(1/η) and
//     only shrinks as the penalty grows, while the matrix grows ill-conditioned.
// Penalty η_f = η · area(f) · (1/vol(K⁻) + 1/vol(K⁺)) (eq. (20)); Dirichlet data weakly.
#include <Eigen/SparseLU>
#include <cmath>
#include <cstdio>

#include "dg/dg_linear_system.hpp"
#include "dg/polyhedral_mesh_faces.hpp"
#include "shared/common/eigen_decompositions.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"
#include "shared/mesh/structured_grid.hpp"

using namespace altfem;

constexpr double lambda = 2.0, mu = 1.5;

// u = (y² + xz, x² − yz, xy + z²): Δu = (2, 2, 2), div u = 2z so ∇ div u = (0, 0, 2), and
// the body force f = −div σ = −μ Δu − (λ + μ) ∇ div u is constant.
Eigen::Vector3d exact_solution(const Eigen::Vector3d& x) {
  return {x.y() * x.y() + x.x() * x.z(), x.x() * x.x() - x.y() * x.z(), x.x() * x.y() + x.z() * x.z()};
}
const Eigen::Vector3d body_force = -mu * Eigen::Vector3d(2, 2, 2) - (lambda + mu) * Eigen::Vector3d(0, 0, 2);

// The grid as DG sees it: every cell a polyhedron, every face once with the cell it
// leaves (minus) and the one it enters (plus, −1 on the boundary, where g acts).
struct DgGrid {
  std::vector<Polyhedron> cells;
  std::vector<dg::DgFace> faces;
};

DgGrid unit_cube_grid(int n) {
  const PolyhedralMesh mesh = polyhedral_mesh_from_volume_mesh(
      structured_grid({Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()}, {n, n, n}, ElementType::hex8));
  DgGrid grid{dg::mesh_cells(mesh), dg::mesh_faces(mesh)};
  for (dg::DgFace& face : grid.faces)
    if (face.plus < 0) face.condition = 0;  // one condition, g, on the whole boundary
  return grid;
}

struct Errors {
  double coefficients;  ///< max |u_h − I u| over the coefficients, relative to max |I u|
  double l2;            ///< ‖u_h − u‖_L2(Ω)
};

// Assembles K and the load (body force and weak Dirichlet data), solves, compares.
Errors solve_and_compare(const DgGrid& grid, dg::Flux flux, double penalty) {
  const dg::DgLinearSystem system(grid.cells, grid.faces, {2, flux, penalty, lambda, mu});
  const Eigen::VectorXd load = system.body_load([](const Eigen::Vector3d&) { return body_force; }) +
                               system.dirichlet_load([](int, const Eigen::Vector3d& x) { return exact_solution(x); });
  const Eigen::SparseLU<Eigen::SparseMatrix<double>> solver(system.stiffness());
  const Eigen::VectorXd solution = solver.solve(load);
  const Eigen::VectorXd interpolant = system.interpolate(exact_solution);
  return {(solution - interpolant).cwiseAbs().maxCoeff() / interpolant.cwiseAbs().maxCoeff(),
          system.l2_error(solution, exact_solution)};
}

int main() {
  const DgGrid grid = unit_cube_grid(3);
  std::printf("3 x 3 x 3 hexahedra, degree 2 (10 monomials per cell and component), lambda = %.1f, mu = %.1f\n\n",
              lambda, mu);
  std::printf("%8s %14s %14s %14s %14s\n", "eta", "IP coeff.", "IP L2", "BZ coeff.", "BZ L2");
  bool ip_exact = true, bz_inconsistent = true, bz_converging = true;
  double previous_bz = INFINITY;
  for (const double penalty : {10.0, 100.0, 1000.0, 10000.0}) {
    const Errors ip = solve_and_compare(grid, dg::Flux::interior_penalty, penalty);
    const Errors bz = solve_and_compare(grid, dg::Flux::babuska_zlamal, penalty);
    std::printf("%8.0f %14.3e %14.3e %14.3e %14.3e\n", penalty, ip.coefficients, ip.l2, bz.coefficients, bz.l2);
    ip_exact = ip_exact && ip.coefficients < 1e-9 && ip.l2 < 1e-9;
    bz_inconsistent = bz_inconsistent && bz.coefficients > 1e-6;
    bz_converging = bz_converging && bz.l2 < previous_bz;
    previous_bz = bz.l2;
  }
  std::printf("\n%s: IP reproduces the quadratic solution to 1e-9 for every eta\n",
              ip_exact ? "verified" : "NOT verified");
  std::printf("%s: BZ does not (error > 1e-6), and its error shrinks as eta grows\n",
              bz_inconsistent && bz_converging ? "verified" : "NOT verified");
  return ip_exact && bz_inconsistent && bz_converging ? 0 : 1;
}
