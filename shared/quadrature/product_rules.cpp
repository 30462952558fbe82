#include "shared/quadrature/product_rules.hpp"

#include "shared/quadrature/gauss_legendre.hpp"

#include <array>
#include <cmath>

namespace altfem {
namespace {

int product_size(int dimension, int n) {
  int total = 1;
  for (int d = 0; d < dimension; ++d) total *= n;
  return total;
}

// Applies `visit(flat, index)` to every multi-index in {0..n−1}^dimension, first
// coordinate fastest.
template <class Visit>
void for_each_multi_index(int dimension, int n, Visit&& visit) {
  std::array<int, 3> index{0, 0, 0};
  for (int flat = 0; flat < product_size(dimension, n); ++flat) {
    for (int d = 0, rest = flat; d < dimension; ++d, rest /= n) index[d] = rest % n;
    visit(flat, index);
  }
}

QuadratureRule tensor_rule(int dimension, int strength) {
  const int n = gauss_point_count(strength);
  const QuadratureRule line = gauss_legendre(n);
  QuadratureRule rule;
  rule.strength = line.strength;
  rule.points.resize(product_size(dimension, n), dimension);
  rule.weights.resize(rule.points.rows());
  for_each_multi_index(dimension, n, [&](int flat, const std::array<int, 3>& index) {
    rule.weights(flat) = 1.0;
    for (int d = 0; d < dimension; ++d) {
      rule.points(flat, d) = line.points(index[d], 0);
      rule.weights(flat) *= line.weights(index[d]);
    }
  });
  return rule;
}

// Stroud's conical product (Approximate Calculation of Multiple Integrals, 1971, §2.7),
// also known as the collapsed-coordinate or Duffy rule: the unit cube (u_0, …, u_{d−1})
// maps onto the unit simplex by x_{d−1} = u_{d−1}, x_k = u_k Π_{j>k} (1 − u_j), with
// Jacobian Π_k (1 − u_k)^k. Coordinate k therefore uses Gauss–Jacobi with weight
// (1 − u)^k, which absorbs the Jacobian, so that a polynomial of total degree m in x
// becomes one of degree <= m in each u_k: n = ⌈(m+1)/2⌉ points per direction suffice.
QuadratureRule collapsed_simplex_rule(int dimension, int strength) {
  const int n = gauss_point_count(strength);
  std::array<QuadratureRule, 3> lines;
  for (int k = 0; k < dimension; ++k) {
    // From [-1,1] with weight (1−t)^k to [0,1] with weight (1−u)^k: u = (1+t)/2,
    // and the weights shrink by 2^{k+1}.
    lines[k] = gauss_jacobi(n, k, 0.0);
    lines[k].points = (lines[k].points.array() + 1.0) / 2.0;
    lines[k].weights /= std::exp2(k + 1);
  }
  QuadratureRule rule;
  rule.strength = lines[0].strength;
  rule.points.resize(product_size(dimension, n), dimension);
  rule.weights.resize(rule.points.rows());
  for_each_multi_index(dimension, n, [&](int flat, const std::array<int, 3>& index) {
    double remaining = 1.0;  // Π_{j>k} (1 − u_j)
    rule.weights(flat) = 1.0;
    for (int k = dimension - 1; k >= 0; --k) {
      const double u = lines[k].points(index[k], 0);
      rule.points(flat, k) = u * remaining;
      rule.weights(flat) *= lines[k].weights(index[k]);
      remaining *= 1.0 - u;
    }
  });
  return rule;
}

}  // namespace

QuadratureRule tensor_quad_rule(int strength) { return tensor_rule(2, strength); }
QuadratureRule tensor_hex_rule(int strength) { return tensor_rule(3, strength); }
QuadratureRule collapsed_triangle_rule(int strength) { return collapsed_simplex_rule(2, strength); }
QuadratureRule collapsed_tet_rule(int strength) { return collapsed_simplex_rule(3, strength); }

}  // namespace altfem
