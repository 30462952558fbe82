#pragma once
// The order of monomials shared by every moment routine and by DG's monomial bases:
// graded by total degree, then lexicographic with the x exponent descending, e.g.
// 3D: 1, x, y, z, x², xy, xz, y², yz, z², x³, …;  2D: 1, x, y, x², xy, y², ….
#include <Eigen/Core>

namespace altfem {

/// Number of monomials x^a y^b z^c with a+b+c <= degree: (d+1)(d+2)(d+3)/6 (0 for degree < 0).
constexpr int monomial_count(int degree) { return degree < 0 ? 0 : (degree + 1) * (degree + 2) * (degree + 3) / 6; }

/// Position of x^a y^b z^c (a, b, c >= 0) in the graded order: all monomials of lower
/// degree come first, then those of degree q = a+b+c ordered by b+c, then by c.
constexpr int monomial_index(int a, int b, int c) {
  const int transverse = b + c;
  return monomial_count(a + b + c - 1) + transverse * (transverse + 1) / 2 + c;
}

/// Number of monomials x^a y^b with a+b <= degree: (d+1)(d+2)/2 (0 for degree < 0).
constexpr int monomial_count_2d(int degree) { return degree < 0 ? 0 : (degree + 1) * (degree + 2) / 2; }

/// Position of x^a y^b (a, b >= 0) in the graded order: lower degrees first, then by b.
constexpr int monomial_index_2d(int a, int b) { return monomial_count_2d(a + b - 1) + b; }

/// monomial_index or monomial_index_2d of an exponent row, as in monomial_exponents[_2d].
inline int monomial_index(const Eigen::Matrix<int, 1, 3>& exponent) {
  return monomial_index(exponent(0), exponent(1), exponent(2));
}
inline int monomial_index(const Eigen::Matrix<int, 1, 2>& exponent) {
  return monomial_index_2d(exponent(0), exponent(1));
}

/// The exponents (a, b, c) of every monomial of degree <= `degree`, in order:
/// monomial_count(degree) × 3. Throws std::invalid_argument for degree < 0.
Eigen::Matrix<int, Eigen::Dynamic, 3> monomial_exponents(int degree);

/// The exponents (a, b) in order: monomial_count_2d(degree) × 2.
/// Throws std::invalid_argument for degree < 0.
Eigen::Matrix<int, Eigen::Dynamic, 2> monomial_exponents_2d(int degree);

}  // namespace altfem
