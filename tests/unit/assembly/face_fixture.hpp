#pragma once
// Tabulated faces for the face-assembler tests and benchmark: the two unit cubes with
// a degree-1 monomial basis sharing the face x = 1 (hand-computable), and grids of
// DG-like faces with random traces (for derivatives, threads and allocations).
#include <Eigen/Core>
#include <random>
#include <vector>

#include "shared/assembly/block_sparsity.hpp"
#include "shared/assembly/tabulated_elements.hpp"
#include "shared/assembly/tabulated_faces.hpp"
#include "shared/quadrature/reference_rules.hpp"

namespace altfem::test {

/// Cube c (0 or 1) is [c, c+1] × [0,1]²; its basis functions 4c..4c+3 are the monomials
/// 1, x − x_c, y − 1/2, z − 1/2 about its centre x_c = (c + 1/2, 1/2, 1/2).
inline Eigen::Vector3d cube_centre(int cube) { return {cube + 0.5, 0.5, 0.5}; }
/// The 4 monomials of cube `cube` at x.
inline Eigen::Vector4d monomials(int cube, const Eigen::Vector3d& x) {
  const Eigen::Vector3d d = x - cube_centre(cube);
  return {1.0, d.x(), d.y(), d.z()};
}
/// Their gradients (4 × 3): 0, e_x, e_y, e_z.
inline Eigen::Matrix<double, 4, 3> monomial_gradients() {
  Eigen::Matrix<double, 4, 3> gradients = Eigen::Matrix<double, 4, 3>::Zero();
  gradients.bottomRows<3>().setIdentity();
  return gradients;
}

/// The face x = 1 between the cubes (minus: cube 0, plus: cube 1, normal +e_x), with
/// quad_rule(strength) mapped onto [0,1]²; basis 0..7.
inline TabulatedFaces two_cube_face(int strength) {
  const QuadratureRule rule = quad_rule(strength);
  const auto points = rule.weights.size();
  std::vector<int> basis{0, 1, 2, 3, 4, 5, 6, 7};
  std::vector<double> weights(points);
  Eigen::MatrixXd normals(points, 3), minus = Eigen::MatrixXd::Zero(points, 8), plus = minus;
  Eigen::MatrixXd gradients_minus = Eigen::MatrixXd::Zero(points * 8, 3), gradients_plus = gradients_minus;
  for (Eigen::Index q = 0; q < points; ++q) {
    weights[q] = rule.weights[q] / 4;  // [-1,1]² → [0,1]²
    normals.row(q) << 1, 0, 0;
    const Eigen::Vector3d x(1.0, 0.5 + rule.points(q, 0) / 2, 0.5 + rule.points(q, 1) / 2);
    minus.block<1, 4>(q, 0) = monomials(0, x).transpose();
    plus.block<1, 4>(q, 4) = monomials(1, x).transpose();
    gradients_minus.block<4, 3>(8 * q, 0) = monomial_gradients();
    gradients_plus.block<4, 3>(8 * q + 4, 0) = monomial_gradients();
  }
  TabulatedFaces faces;
  faces.add(basis, weights, normals, minus, plus, gradients_minus, gradients_plus, 0, 1);
  return faces;
}

/// Appends cube 0's boundary face x = 0 (minus: cube 0, no plus side, normal −e_x),
/// basis 0..3: with a jump penalty, a weak clamp u = 0.
inline void add_clamped_face(TabulatedFaces& faces, int strength) {
  const QuadratureRule rule = quad_rule(strength);
  const auto points = rule.weights.size();
  std::vector<int> basis{0, 1, 2, 3};
  std::vector<double> weights(points);
  Eigen::MatrixXd normals(points, 3), minus(points, 4), plus = Eigen::MatrixXd::Zero(points, 4);
  Eigen::MatrixXd gradients_minus(points * 4, 3), gradients_plus = Eigen::MatrixXd::Zero(points * 4, 3);
  for (Eigen::Index q = 0; q < points; ++q) {
    weights[q] = rule.weights[q] / 4;
    normals.row(q) << -1, 0, 0;
    minus.row(q) =
        monomials(0, Eigen::Vector3d(0.0, 0.5 + rule.points(q, 0) / 2, 0.5 + rule.points(q, 1) / 2)).transpose();
    gradients_minus.block<4, 3>(4 * q, 0) = monomial_gradients();
  }
  faces.add(basis, weights, normals, minus, plus, gradients_minus, gradients_plus, 0, -1);
}

/// The two cubes as volume elements (hex_rule(strength) mapped onto each cube).
inline TabulatedElements two_cube_elements(int strength) {
  const QuadratureRule rule = hex_rule(strength);
  const auto points = rule.weights.size();
  TabulatedElements elements;
  for (int cube = 0; cube < 2; ++cube) {
    std::vector<int> basis{4 * cube, 4 * cube + 1, 4 * cube + 2, 4 * cube + 3};
    std::vector<double> weights(points);
    Eigen::MatrixXd values(points, 4), gradients(points * 4, 3);
    for (Eigen::Index q = 0; q < points; ++q) {
      weights[q] = rule.weights[q] / 8;
      const Eigen::Vector3d x = cube_centre(cube) + rule.points.row(q).transpose() / 2;
      values.row(q) = monomials(cube, x).transpose();
      gradients.block<4, 3>(4 * q, 0) = monomial_gradients();
    }
    elements.add(basis, weights, values, gradients);
  }
  return elements;
}

/// Appends a face with random traces: `basis` split into the minus side's first
/// `minus_count` functions and the plus side's rest (zero trace on the other side,
/// as in DG), random positive weights and random unit normals.
inline void add_random_face(TabulatedFaces& faces, const std::vector<int>& basis, int minus_count, int points,
                            std::mt19937& random, int minus = 0, int plus = 1) {
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const auto n = static_cast<Eigen::Index>(basis.size());
  std::vector<double> weights(points);
  Eigen::MatrixXd normals(points, 3), values_minus = Eigen::MatrixXd::Zero(points, n), values_plus = values_minus;
  Eigen::MatrixXd gradients_minus = Eigen::MatrixXd::Zero(points * n, 3), gradients_plus = gradients_minus;
  for (int q = 0; q < points; ++q) {
    weights[q] = 0.5 + 0.25 * uniform(random);
    Eigen::Vector3d normal(uniform(random), uniform(random), uniform(random));
    normals.row(q) = (normal + Eigen::Vector3d(2, 0, 0)).normalized().transpose();
    for (Eigen::Index a = 0; a < n; ++a) {
      const bool on_minus = a < minus_count;
      (on_minus ? values_minus : values_plus)(q, a) = uniform(random);
      for (int i = 0; i < 3; ++i) (on_minus ? gradients_minus : gradients_plus)(q * n + a, i) = uniform(random);
    }
  }
  faces.add(basis, weights, normals, values_minus, values_plus, gradients_minus, gradients_plus, minus, plus);
}

/// DG-like faces of an n³ grid of cells: cell c owns its own consecutive basis
/// functions (cell_sizes[c] of them) and every pair of x-, y- or z-neighbours shares a
/// face of `points` random points. Face sizes are the sums of its cells' sizes.
inline TabulatedFaces grid_faces(int n, const std::vector<int>& cell_sizes, int points, unsigned seed) {
  std::vector<int> first{0};
  for (int size : cell_sizes) first.push_back(first.back() + size);
  const auto cell = [n](int i, int j, int k) { return i + n * (j + n * k); };
  std::mt19937 random(seed);
  TabulatedFaces faces;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (const Eigen::Vector3i& step :
             {Eigen::Vector3i(1, 0, 0), Eigen::Vector3i(0, 1, 0), Eigen::Vector3i(0, 0, 1)}) {
          const Eigen::Vector3i other = Eigen::Vector3i(i, j, k) + step;
          if (other.maxCoeff() >= n) continue;
          const int minus = cell(i, j, k), plus = cell(other.x(), other.y(), other.z());
          std::vector<int> basis;
          for (int c : {minus, plus})
            for (int a = first[c]; a < first[c + 1]; ++a) basis.push_back(a);
          add_random_face(faces, basis, cell_sizes[minus], points, random, minus, plus);
        }
  return faces;
}

/// Random per-cell sizes drawn from `sizes`.
inline std::vector<int> random_cell_sizes(int cells, const std::vector<int>& sizes, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_int_distribution<size_t> pick(0, sizes.size() - 1);
  std::vector<int> result(cells);
  for (int& size : result) size = sizes[pick(random)];
  return result;
}

}  // namespace altfem::test
