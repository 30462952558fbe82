// Example 7: the 2D Poisson teaching case of Martin et al. 2008 (§7–8, Fig. 6) —
// polygonal elements with harmonic bases make adaptive refinement free of hanging nodes.
//
//   build/bin/ex7_harmonic_poisson2d
//
// Problem: −Δu = f on Ω = [0,1]², u = g on ∂Ω, with the known "wave front" solution
//   u(x) = atan(α (r − r₀)),  r = ‖x − c‖,  c = (−0.05, −0.05), r₀ = 0.7, α = 20,
// a smooth step across a circular arc: most of Ω is flat, the front is steep.
//
// Mesh: a quadtree of square cells. Uniform refinement splits every cell; adaptive
// refinement splits only where the error estimate h³·|D²u| is large, and
// does NOT balance neighbours. A bilinear FEM would then need hanging-node constraints;
// here a coarse cell next to finer ones simply becomes a POLYGON whose vertices include
// its neighbours' corners on its edges (Martin et al. §7, Fig. 4): still one node per
// vertex, still a conforming basis.
//
// Basis: on every polygon, the 2D harmonic coordinates N_i (ΔN_i = 0 inside; 1 at vertex
// i, 0 at the others, linear along each edge) by the method of fundamental solutions,
// kernel log r plus a linear polynomial (eq. (11) in 2D; polyhedral/face_harmonic_coordinates).
// On a square they are (nearly) the bilinear functions; on a polygon with hanging vertices
// they are what makes the basis continuous across the T-junction: both sides see the same
// piecewise-linear trace on a shared edge.
//
// Galerkin: K_ij = ∫ ∇N_i·∇N_j, F_i = ∫ f N_i, Dirichlet nodes set to g (strongly, as the
// basis is nodal), solved by sparse Cholesky. The program prints the L2 error and κ(K) of
// the free-free block against DOFs for both refinements, as Fig. 6 does, and checks
// (exit 1 otherwise) that uniform refinement converges at L2 rate ≥ 1.8 and that adaptive
// refinement reaches the finest uniform error with fewer DOFs.
#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/MatOp/SparseSymShiftSolve.h>
#include <Spectra/SymEigsShiftSolver.h>
#include <Spectra/SymEigsSolver.h>
#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>

#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <set>
#include <vector>

#include "polyhedral/face_harmonic_coordinates.hpp"
#include "shared/common/eigen_decompositions.hpp"
#include "shared/quadrature/gauss_legendre.hpp"

using namespace altfem;

// ---------------------------------------------------------------------------------------
// 1. The exact solution, its load f = −Δu and its Hessian's size (for the refinement).
//    For a radial u(r): Δu = u'' + u'/r, and D²u has eigenvalues u'' and u'/r.
// ---------------------------------------------------------------------------------------
constexpr double alpha = 20, front_radius = 0.7;
const Eigen::Vector2d front_centre(-0.05, -0.05);

struct Radial {
  double value, first, second, radius;
};
Radial radial(const Eigen::Vector2d& x) {
  const double r = (x - front_centre).norm(), s = alpha * (r - front_radius);
  return {std::atan(s), alpha / (1 + s * s), -2 * alpha * alpha * s / ((1 + s * s) * (1 + s * s)), r};
}
double exact(const Eigen::Vector2d& x) { return radial(x).value; }
double load(const Eigen::Vector2d& x) {
  const Radial u = radial(x);
  return -(u.second + u.first / u.radius);
}
double hessian_size(const Eigen::Vector2d& x) {
  const Radial u = radial(x);
  return std::max(std::abs(u.second), std::abs(u.first / u.radius));
}

// ---------------------------------------------------------------------------------------
// 2. The quadtree. Cells and nodes live on an integer lattice of spacing 2^-depth_limit:
//    a cell of level l has side 2^(depth_limit − l) lattice units.
// ---------------------------------------------------------------------------------------
constexpr int depth_limit = 9;
constexpr int lattice = 1 << depth_limit;

struct Cell {
  int x, y, side;  // lower-left corner and side, in lattice units
};
using Lattice = std::pair<int, int>;

// Leaves of the tree from the unit square down: `split(cell)` says whether to split.
std::vector<Cell> quadtree(const std::function<bool(const Cell&)>& split) {
  std::vector<Cell> leaves, pending{{0, 0, lattice}};
  while (!pending.empty()) {
    const Cell cell = pending.back();
    pending.pop_back();
    if (cell.side > 1 && split(cell)) {
      const int half = cell.side / 2;
      for (int k = 0; k < 4; ++k) pending.push_back({cell.x + (k & 1) * half, cell.y + (k >> 1) * half, half});
    } else {
      leaves.push_back(cell);
    }
  }
  return leaves;
}

Eigen::Vector2d position(const Lattice& point) {
  return Eigen::Vector2d(point.first, point.second) / static_cast<double>(lattice);
}

// ---------------------------------------------------------------------------------------
// 3. Polygons: every leaf's boundary, counter-clockwise, through every node (a corner of
//    any leaf) that lies on it. No hanging-node constraints: those nodes are vertices.
// ---------------------------------------------------------------------------------------
struct PolygonMesh {
  std::vector<Eigen::Vector2d> nodes;
  std::vector<std::vector<int>> polygons;  // node indices, counter-clockwise
  std::vector<Cell> cells;                 // the square each polygon covers
};

PolygonMesh polygon_mesh(const std::vector<Cell>& leaves) {
  std::set<Lattice> corners;
  for (const Cell& c : leaves)
    for (int k = 0; k < 4; ++k) corners.insert({c.x + (k & 1) * c.side, c.y + (k >> 1) * c.side});
  PolygonMesh mesh;
  std::map<Lattice, int> index;
  for (const Lattice& corner : corners) {
    index[corner] = static_cast<int>(mesh.nodes.size());
    mesh.nodes.push_back(position(corner));
  }
  for (const Cell& c : leaves) {
    std::vector<int> polygon;
    // Walk the four sides: bottom (→), right (↑), top (←), left (↓), one lattice step at a time.
    const int steps[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    Lattice at{c.x, c.y};
    for (const auto& step : steps)
      for (int k = 0; k < c.side; ++k) {
        if (corners.count(at)) polygon.push_back(index[at]);
        at = {at.first + step[0], at.second + step[1]};
      }
    mesh.polygons.push_back(polygon);
    mesh.cells.push_back(c);
  }
  return mesh;
}

// ---------------------------------------------------------------------------------------
// 4. Assemble, solve, measure. Each square is integrated by a tensor Gauss rule (the
//    harmonic basis is smooth inside, its kinks sit on the boundary). The stiffness rule
//    has 4 × 4 points, the L2 error is measured with 6 × 6.
// ---------------------------------------------------------------------------------------
struct Result {
  int dofs = 0;          // free nodes
  int max_vertices = 0;  // of any polygon
  double l2_error = 0, condition = 0;
};

// Tensor rule on a cell: points (#points × 2) and weights.
void square_rule(const Cell& cell, int order, Eigen::MatrixX2d& points, Eigen::VectorXd& weights) {
  const QuadratureRule line = gauss_legendre(order);
  const double h = static_cast<double>(cell.side) / lattice;
  const Eigen::Vector2d origin = position({cell.x, cell.y});
  points.resize(order * order, 2);
  weights.resize(order * order);
  for (int i = 0; i < order; ++i)
    for (int j = 0; j < order; ++j) {
      points.row(i * order + j) =
          origin.transpose() + 0.5 * h * Eigen::RowVector2d(line.points(i, 0) + 1, line.points(j, 0) + 1);
      weights[i * order + j] = 0.25 * h * h * line.weights[i] * line.weights[j];
    }
}

// κ₂ of an SPD sparse matrix: its largest and smallest eigenvalues (Lanczos; the
// smallest by shift-invert about 0, one sparse factorisation); dense when small.
double condition_number(const Eigen::SparseMatrix<double>& matrix) {
  if (matrix.rows() <= 100) {
    const Eigen::VectorXd eigenvalues =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(matrix)).eigenvalues();
    return eigenvalues.maxCoeff() / eigenvalues.minCoeff();
  }
  Spectra::SparseSymMatProd<double> product(matrix);
  Spectra::SymEigsSolver<Spectra::SparseSymMatProd<double>> largest(product, 1, 20);
  largest.init();
  largest.compute(Spectra::SortRule::LargestAlge);
  Spectra::SparseSymShiftSolve<double> inverse(matrix);
  Spectra::SymEigsShiftSolver<Spectra::SparseSymShiftSolve<double>> smallest(inverse, 1, 20, 0.0);
  smallest.init();
  smallest.compute(Spectra::SortRule::LargestMagn);
  return largest.eigenvalues()[0] / smallest.eigenvalues()[0];
}

Result solve(const PolygonMesh& mesh) {
  const int n = static_cast<int>(mesh.nodes.size());
  // Boundary nodes carry g; the others are unknowns, numbered 0 .. dofs−1.
  std::vector<int> unknown(n, -1);
  Eigen::VectorXd solution = Eigen::VectorXd::Zero(n);
  Result result;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d& x = mesh.nodes[i];
    const bool boundary = x.x() == 0 || x.y() == 0 || x.x() == 1 || x.y() == 1;
    if (boundary) solution[i] = exact(x);
    else unknown[i] = result.dofs++;
  }
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(result.dofs);
  std::vector<harmonic::FaceHarmonicCoordinates> bases;
  harmonic::MfsOptions options;
  options.edge_samples = 3;
  Eigen::MatrixX2d points;
  Eigen::VectorXd weights;
  for (size_t e = 0; e < mesh.polygons.size(); ++e) {
    const std::vector<int>& polygon = mesh.polygons[e];
    const int k = static_cast<int>(polygon.size());
    result.max_vertices = std::max(result.max_vertices, k);
    Eigen::MatrixXd vertices = Eigen::MatrixXd::Zero(k, 3);  // in the plane z = 0
    for (int a = 0; a < k; ++a) vertices.row(a).head<2>() = mesh.nodes[polygon[a]].transpose();
    bases.emplace_back(vertices, options);
    square_rule(mesh.cells[e], 4, points, weights);
    for (Eigen::Index q = 0; q < weights.size(); ++q) {
      const Eigen::Vector3d x(points(q, 0), points(q, 1), 0);
      const Eigen::MatrixX3d gradients = bases.back().gradients(x);                     // k × 3
      const Eigen::VectorXd values = bases.back().evaluate(x.transpose()).transpose();  // k
      const Eigen::MatrixXd local = weights[q] * gradients * gradients.transpose();     // ∫ ∇N_a·∇N_b
      for (int a = 0; a < k; ++a) {
        const int row = unknown[polygon[a]];
        if (row < 0) continue;
        rhs[row] += weights[q] * load(points.row(q).transpose()) * values[a];
        for (int b = 0; b < k; ++b) {
          const int column = unknown[polygon[b]];
          if (column >= 0) triplets.emplace_back(row, column, local(a, b));
          else rhs[row] -= local(a, b) * solution[polygon[b]];  // move the known g to the right
        }
      }
    }
  }
  Eigen::SparseMatrix<double> stiffness(result.dofs, result.dofs);
  stiffness.setFromTriplets(triplets.begin(), triplets.end());
  const Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> cholesky(stiffness);
  const Eigen::VectorXd free = cholesky.solve(rhs);
  for (int i = 0; i < n; ++i)
    if (unknown[i] >= 0) solution[i] = free[unknown[i]];
  // ‖u − u_h‖_L2 with u_h = Σ_a u_a N_a on each polygon.
  double squared = 0;
  for (size_t e = 0; e < mesh.polygons.size(); ++e) {
    square_rule(mesh.cells[e], 6, points, weights);
    Eigen::MatrixXd at(points.rows(), 3);
    at << points, Eigen::VectorXd::Zero(points.rows());
    const Eigen::MatrixXd values = bases[e].evaluate(at);  // #points × k
    Eigen::VectorXd coefficients(static_cast<Eigen::Index>(mesh.polygons[e].size()));
    for (Eigen::Index a = 0; a < coefficients.size(); ++a) coefficients[a] = solution[mesh.polygons[e][a]];
    const Eigen::VectorXd approximate = values * coefficients;
    for (Eigen::Index q = 0; q < weights.size(); ++q)
      squared += weights[q] * std::pow(approximate[q] - exact(points.row(q).transpose()), 2);
  }
  result.l2_error = std::sqrt(squared);
  result.condition = condition_number(stiffness);
  return result;
}

// ---------------------------------------------------------------------------------------
// 5. Both refinements, and the two checks.
// ---------------------------------------------------------------------------------------
int main() {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // each table row as it is computed
  // Uniform: every cell down to level L (2^L × 2^L squares).
  std::printf("uniform refinement (squares; the MFS basis ≈ bilinear)\n");
  std::printf("  level   cells    DOFs   max vertices   L2 error     rate   κ(K)\n");
  std::vector<Result> uniform;
  for (int level = 2; level <= 7; ++level) {
    const int side = lattice >> level;
    const Result r = solve(polygon_mesh(quadtree([&](const Cell& c) { return c.side > side; })));
    // Rate in h: DOFs ~ h⁻², so rate = −2 Δlog e / Δlog DOFs.
    const double rate = uniform.empty() ? NAN
                                        : -2 * std::log(r.l2_error / uniform.back().l2_error) /
                                              std::log(static_cast<double>(r.dofs) / uniform.back().dofs);
    std::printf("  %5d %7d %7d %14d   %.3e  %5.2f   %.3e\n", level, 1 << (2 * level), r.dofs, r.max_vertices,
                r.l2_error, rate, r.condition);
    uniform.push_back(r);
  }
  // Adaptive: split a cell while h³·max|D²u| over its corners and centre exceeds a
  // tolerance — h²|D²u| bounds the bilinear interpolation error on the cell, and one more
  // h (the square root of its area) makes it the cell's share of the L2 error, which the
  // refinement equidistributes; at least level 2, no balancing.
  std::printf("adaptive refinement (quadtree without balancing: polygons with hanging vertices)\n");
  std::printf("  tolerance  cells    DOFs   max vertices   L2 error            κ(K)\n");
  std::vector<Result> adaptive;
  std::vector<int> cell_counts;
  for (double tolerance = 1e-2; tolerance >= 1e-2 / 200; tolerance /= 2) {
    const auto split = [&](const Cell& c) {
      const double h = static_cast<double>(c.side) / lattice;
      if (h > 0.25) return true;
      double size = 0;
      for (int k = 0; k < 5; ++k) {
        const Eigen::Vector2d corner = k < 4 ? position({c.x + (k & 1) * c.side, c.y + (k >> 1) * c.side})
                                             : position({c.x, c.y}) + Eigen::Vector2d(h, h) / 2;
        size = std::max(size, hessian_size(corner));
      }
      return h * h * h * size > tolerance;
    };
    const std::vector<Cell> leaves = quadtree(split);
    const Result r = solve(polygon_mesh(leaves));
    std::printf("  %9.2e %6zu %7d %14d   %.3e           %.3e\n", tolerance, leaves.size(), r.dofs, r.max_vertices,
                r.l2_error, r.condition);
    adaptive.push_back(r);
  }

  // Check 1: the uniform L2 rate at the two finest levels (bilinear-like: 2).
  const Result& finest = uniform.back();
  const Result& before = uniform[uniform.size() - 2];
  const double rate =
      -2 * std::log(finest.l2_error / before.l2_error) / std::log(static_cast<double>(finest.dofs) / before.dofs);
  // Check 2: the fewest adaptive DOFs that reach the finest uniform error.
  int adaptive_dofs = -1;
  for (const Result& r : adaptive)
    if (r.l2_error <= finest.l2_error && (adaptive_dofs < 0 || r.dofs < adaptive_dofs)) adaptive_dofs = r.dofs;
  std::printf("uniform L2 rate at the finest levels: %.2f (need >= 1.8)\n", rate);
  std::printf("L2 error %.3e: uniform with %d DOFs, adaptive with %d DOFs\n", finest.l2_error, finest.dofs,
              adaptive_dofs);
  const bool rate_ok = rate >= 1.8;
  const bool adaptive_ok = adaptive_dofs > 0 && adaptive_dofs < finest.dofs;
  if (!rate_ok) std::printf("FAILED: the uniform L2 rate is below 1.8\n");
  if (!adaptive_ok) std::printf("FAILED: adaptive refinement did not reach the uniform error with fewer DOFs\n");
  return rate_ok && adaptive_ok ? 0 : 1;
}
