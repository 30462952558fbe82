#include "shared/quadrature/gauss_legendre.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <stdexcept>
#include <string>

#include "shared/common/eigen_decompositions.hpp"

namespace altfem {
namespace {

// Three-term recurrence of the monic Jacobi polynomials,
// π_{k+1}(x) = (x − a_k) π_k(x) − b_k π_{k−1}(x)   (Gautschi, Orthogonal Polynomials:
// Computation and Approximation, 2004, Table 1.1). a_0 and b_1 are the limits of the
// general formulas, which are 0/0 when alpha + beta is 0 or −1.
struct JacobiRecurrence {
  Eigen::VectorXd a;  // n: a_0 … a_{n−1}
  Eigen::VectorXd b;  // n+1: b_0 = μ_0 = ∫ weight, b_1 … b_n
};

JacobiRecurrence jacobi_recurrence(int n, double alpha, double beta) {
  const double s = alpha + beta;
  JacobiRecurrence r{Eigen::VectorXd(n), Eigen::VectorXd(n + 1)};
  r.a(0) = (beta - alpha) / (s + 2.0);
  for (int k = 1; k < n; ++k) r.a(k) = (beta * beta - alpha * alpha) / ((2.0 * k + s) * (2.0 * k + s + 2.0));
  r.b(0) = std::exp2(s + 1.0) * std::tgamma(alpha + 1.0) * std::tgamma(beta + 1.0) / std::tgamma(s + 2.0);
  if (n >= 1) r.b(1) = 4.0 * (1.0 + alpha) * (1.0 + beta) / ((2.0 + s) * (2.0 + s) * (3.0 + s));
  for (int k = 2; k <= n; ++k) {
    const double t = 2.0 * k + s;
    r.b(k) = 4.0 * k * (k + alpha) * (k + beta) * (k + s) / (t * t * (t + 1.0) * (t - 1.0));
  }
  return r;
}

// The orthonormal polynomials p_0 … p_n at x and p_n'(x), from the recurrence
// √b_{k+1} p_{k+1} = (x − a_k) p_k − √b_k p_{k−1}.
struct OrthonormalValues {
  double sum_of_squares = 0;  // Σ_{k<n} p_k(x)², whose inverse is the Christoffel number
  double value = 0;           // p_n(x)
  double derivative = 0;      // p_n'(x)
};

OrthonormalValues orthonormal_values(const JacobiRecurrence& r, int n, double x) {
  double p_previous = 0, p = 1.0 / std::sqrt(r.b(0));
  double d_previous = 0, d = 0;
  OrthonormalValues result;
  for (int k = 0; k < n; ++k) {
    result.sum_of_squares += p * p;
    const double root_next = std::sqrt(r.b(k + 1));
    const double root_current = k == 0 ? 0.0 : std::sqrt(r.b(k));
    const double p_next = ((x - r.a(k)) * p - root_current * p_previous) / root_next;
    const double d_next = (p + (x - r.a(k)) * d - root_current * d_previous) / root_next;
    p_previous = p, p = p_next;
    d_previous = d, d = d_next;
  }
  result.value = p;
  result.derivative = d;
  return result;
}

}  // namespace

QuadratureRule gauss_jacobi(int point_count, double alpha, double beta) {
  if (point_count < 1)
    throw std::invalid_argument("gauss_jacobi: point count must be >= 1, got " + std::to_string(point_count));
  if (!(alpha > -1.0) || !(beta > -1.0))
    throw std::invalid_argument("gauss_jacobi: alpha and beta must be > -1, got " + std::to_string(alpha) + ", " +
                                std::to_string(beta));
  const int n = point_count;
  const JacobiRecurrence recurrence = jacobi_recurrence(n, alpha, beta);

  // Golub–Welsch (Math. Comp. 23, 1969): the nodes are the eigenvalues of the symmetric
  // tridiagonal Jacobi matrix; Eigen's tridiagonal QR is stable for any n.
  Eigen::VectorXd off_diagonal(n - 1);
  for (int k = 1; k < n; ++k) off_diagonal(k - 1) = std::sqrt(recurrence.b(k));
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver;
  solver.computeFromTridiagonal(recurrence.a, off_diagonal, Eigen::EigenvaluesOnly);

  QuadratureRule rule;
  rule.points.resize(n, 1);
  rule.weights.resize(n);
  rule.strength = 2 * n - 1;
  for (int i = 0; i < n; ++i) {
    // One Newton step on p_n polishes the eigenvalue to the last bit, and the weight
    // comes from the Christoffel function w = 1 / Σ p_k(x)² rather than from the
    // eigenvector, whose small components have poor relative accuracy.
    double x = solver.eigenvalues()(i);
    const OrthonormalValues at_eigenvalue = orthonormal_values(recurrence, n, x);
    if (at_eigenvalue.derivative != 0.0) x -= at_eigenvalue.value / at_eigenvalue.derivative;
    rule.points(i, 0) = x;
    rule.weights(i) = 1.0 / orthonormal_values(recurrence, n, x).sum_of_squares;
  }
  return rule;
}

QuadratureRule gauss_legendre(int point_count) {
  if (point_count < 1)
    throw std::invalid_argument("gauss_legendre: point count must be >= 1, got " + std::to_string(point_count));
  return gauss_jacobi(point_count, 0.0, 0.0);
}

int gauss_point_count(int strength) {
  if (strength < 0) throw std::invalid_argument("quadrature strength must be >= 0, got " + std::to_string(strength));
  return strength / 2 + 1;
}

}  // namespace altfem
