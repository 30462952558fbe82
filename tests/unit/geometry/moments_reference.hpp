#pragma once
// Independent reference integrals for the moment tests: the analytic product formula on
// boxes, and Gauss quadrature on simplices (altfem_quadrature's collapsed rules, exact
// for polynomials of the rule's strength) over a signed cone decomposition. Each
// reference also returns ∫|f|, the denominator of the project's relative error
// |err| / max(|exact|, ∫|f|) (docs/conventions.md, "Numerical conventions").
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <vector>

#include "shared/geometry/monomial_index.hpp"
#include "shared/geometry/polyhedron.hpp"
#include "shared/quadrature/product_rules.hpp"

namespace altfem::test {

struct ReferenceMoments {
  Eigen::VectorXd exact;     ///< ∫ x^α
  Eigen::VectorXd absolute;  ///< ∫ |x^α| (or an upper bound of it)
};

/// ∫_low^high x^a dx for a = 0..degree, written about the interval's midpoint m with
/// half-width h, Σ_{i even} C(a,i) m^(a−i) 2h^(i+1)/(i+1): every term has the sign of m^a,
/// so a tiny interval far from 0 loses nothing to cancellation (x1^(a+1) − x0^(a+1) would).
inline ReferenceMoments interval_moments(double low, double high, int degree) {
  const double middle = 0.5 * (low + high);
  const double half = 0.5 * (high - low);
  ReferenceMoments result{Eigen::VectorXd(degree + 1), Eigen::VectorXd(degree + 1)};
  for (int a = 0; a <= degree; ++a) {
    double sum = 0.0;
    double binomial = 1.0;  // C(a, i)
    for (int i = 0; i <= a; ++i) {
      if (i % 2 == 0) sum += binomial * std::pow(middle, a - i) * 2.0 * std::pow(half, i + 1) / (i + 1);
      binomial *= static_cast<double>(a - i) / (i + 1);
    }
    result.exact(a) = sum;
    result.absolute(a) =
        (low >= 0.0 || high <= 0.0) ? std::abs(sum) : (std::pow(-low, a + 1) + std::pow(high, a + 1)) / (a + 1);
  }
  return result;
}

/// Moments of the box [low, high] by the product formula, monomial_index order.
inline ReferenceMoments box_moments(const Eigen::Vector3d& low, const Eigen::Vector3d& high, int degree) {
  const ReferenceMoments x = interval_moments(low.x(), high.x(), degree);
  const ReferenceMoments y = interval_moments(low.y(), high.y(), degree);
  const ReferenceMoments z = interval_moments(low.z(), high.z(), degree);
  const auto exponents = monomial_exponents(degree);
  ReferenceMoments result{Eigen::VectorXd(exponents.rows()), Eigen::VectorXd(exponents.rows())};
  for (Eigen::Index row = 0; row < exponents.rows(); ++row) {
    const int a = exponents(row, 0), b = exponents(row, 1), c = exponents(row, 2);
    result.exact(row) = x.exact(a) * y.exact(b) * z.exact(c);
    result.absolute(row) = x.absolute(a) * y.absolute(b) * z.absolute(c);
  }
  return result;
}

/// The 2D box [low, high], monomial_index_2d order.
inline ReferenceMoments rectangle_moments(const Eigen::Vector2d& low, const Eigen::Vector2d& high, int degree) {
  const ReferenceMoments x = interval_moments(low.x(), high.x(), degree);
  const ReferenceMoments y = interval_moments(low.y(), high.y(), degree);
  const auto exponents = monomial_exponents_2d(degree);
  ReferenceMoments result{Eigen::VectorXd(exponents.rows()), Eigen::VectorXd(exponents.rows())};
  for (Eigen::Index row = 0; row < exponents.rows(); ++row) {
    result.exact(row) = x.exact(exponents(row, 0)) * y.exact(exponents(row, 1));
    result.absolute(row) = x.absolute(exponents(row, 0)) * y.absolute(exponents(row, 1));
  }
  return result;
}

/// Sum of the moments of disjoint pieces.
inline ReferenceMoments sum_of(const std::vector<ReferenceMoments>& pieces) {
  ReferenceMoments total{Eigen::VectorXd::Zero(pieces.front().exact.size()),
                         Eigen::VectorXd::Zero(pieces.front().exact.size())};
  for (const ReferenceMoments& piece : pieces) {
    total.exact += piece.exact;
    total.absolute += piece.absolute;
  }
  return total;
}

/// Monomial values at a point of dimension 2 or 3, in that dimension's order.
inline Eigen::VectorXd monomial_values(const Eigen::VectorXd& point, int degree) {
  Eigen::VectorXd values;
  if (point.size() == 3) {
    const auto exponents = monomial_exponents(degree);
    values.resize(exponents.rows());
    for (Eigen::Index row = 0; row < exponents.rows(); ++row) {
      values(row) = std::pow(point(0), exponents(row, 0)) * std::pow(point(1), exponents(row, 1)) *
                    std::pow(point(2), exponents(row, 2));
    }
  } else {
    const auto exponents = monomial_exponents_2d(degree);
    values.resize(exponents.rows());
    for (Eigen::Index row = 0; row < exponents.rows(); ++row) {
      values(row) = std::pow(point(0), exponents(row, 0)) * std::pow(point(1), exponents(row, 1));
    }
  }
  return values;
}

/// Adds ∫ over the simplex `origin + jacobian·(unit simplex)` (signed by det jacobian)
/// with the collapsed Gauss rule of strength `degree`; `map` takes a simplex point to the
/// point where the monomials are evaluated (identity, or an embedding of 2D into 3D).
template <typename Map>
void add_simplex(ReferenceMoments& sum, const Eigen::VectorXd& origin, const Eigen::MatrixXd& jacobian, int degree,
                 const Map& map) {
  const QuadratureRule rule = jacobian.rows() == 3 ? collapsed_tet_rule(degree) : collapsed_triangle_rule(degree);
  const double determinant = jacobian.determinant();
  for (Eigen::Index q = 0; q < rule.weights.size(); ++q) {
    const Eigen::VectorXd point = origin + jacobian * rule.points.row(q).transpose();
    const Eigen::VectorXd values = monomial_values(map(point), degree);
    sum.exact += determinant * rule.weights(q) * values;
    sum.absolute += std::abs(determinant) * rule.weights(q) * values.cwiseAbs();
  }
}

/// ∫_P x^α by cones from `apex` over each face, each face fanned from its vertex mean:
/// the signed tetrahedra add up to P's winding number, so this holds for any closed
/// oriented polyhedron; `absolute` is exact only if no tetrahedron is inverted.
inline ReferenceMoments cone_quadrature_moments(const Polyhedron& polyhedron, const Eigen::Vector3d& apex, int degree) {
  ReferenceMoments sum{Eigen::VectorXd::Zero(monomial_count(degree)), Eigen::VectorXd::Zero(monomial_count(degree))};
  for (const std::vector<int>& face : polyhedron.faces) {
    Eigen::Vector3d face_centre = Eigen::Vector3d::Zero();
    for (const int v : face) face_centre += polyhedron.vertices.row(v).transpose();
    face_centre /= static_cast<double>(face.size());
    for (std::size_t i = 0; i < face.size(); ++i) {
      Eigen::Matrix3d jacobian;
      jacobian.col(0) = face_centre - apex;
      jacobian.col(1) = polyhedron.vertices.row(face[i]).transpose() - apex;
      jacobian.col(2) = polyhedron.vertices.row(face[(i + 1) % face.size()]).transpose() - apex;
      add_simplex(sum, apex, jacobian, degree, [](const Eigen::VectorXd& x) { return x; });
    }
  }
  return sum;
}

/// ∫ over a 2D polygon (#v × 2) of the monomials of map(x) (2D or 3D), by triangles
/// fanned from `apex`; signed like the polygon's orientation.
template <typename Map>
ReferenceMoments fan_quadrature_moments(const Eigen::MatrixXd& polygon, const Eigen::Vector2d& apex, int degree,
                                        const Map& map, int count) {
  ReferenceMoments sum{Eigen::VectorXd::Zero(count), Eigen::VectorXd::Zero(count)};
  for (Eigen::Index i = 0; i < polygon.rows(); ++i) {
    Eigen::Matrix2d jacobian;
    jacobian.col(0) = polygon.row(i).transpose() - apex;
    jacobian.col(1) = polygon.row((i + 1) % polygon.rows()).transpose() - apex;
    add_simplex(sum, apex, jacobian, degree, map);
  }
  return sum;
}

/// The axis-aligned box [low, high] with quadrilateral faces, outward counter-clockwise.
inline Polyhedron box(const Eigen::Vector3d& low, const Eigen::Vector3d& high) {
  Polyhedron result;
  result.vertices.resize(8, 3);
  for (int i = 0; i < 8; ++i) {
    result.vertices.row(i) << (i & 1 ? high.x() : low.x()), (i & 2 ? high.y() : low.y()), (i & 4 ? high.z() : low.z());
  }
  result.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  return result;
}

/// The prism polygon × [z0, z1] over a simple counter-clockwise 2D polygon (#v × 2):
/// bottom and top faces are the (possibly non-convex) polygon itself, sides are quads.
inline Polyhedron extrude(const Eigen::MatrixXd& polygon, double z0, double z1) {
  const int n = static_cast<int>(polygon.rows());
  Polyhedron result;
  result.vertices.resize(2 * n, 3);
  for (int i = 0; i < n; ++i) {
    result.vertices.row(i) << polygon(i, 0), polygon(i, 1), z0;
    result.vertices.row(n + i) << polygon(i, 0), polygon(i, 1), z1;
  }
  std::vector<int> bottom, top;
  for (int i = 0; i < n; ++i) {
    bottom.push_back(n - 1 - i);
    top.push_back(n + i);
    const int j = (i + 1) % n;
    result.faces.push_back({i, j, n + j, n + i});
  }
  result.faces.push_back(bottom);
  result.faces.push_back(top);
  return result;
}

/// x ↦ rotation·x + translation applied to every vertex.
inline Polyhedron transformed(Polyhedron polyhedron, const Eigen::Matrix3d& rotation,
                              const Eigen::Vector3d& translation) {
  polyhedron.vertices = (polyhedron.vertices * rotation.transpose()).rowwise() + translation.transpose();
  return polyhedron;
}

/// A fixed, generic rotation (no face stays axis-aligned).
inline Eigen::Matrix3d generic_rotation() {
  return Eigen::Quaterniond(0.8, -0.3, 0.5, 0.2).normalized().toRotationMatrix();
}

/// Every moment within `tolerance` in the project's relative error.
inline void expect_moments_near(const Eigen::VectorXd& computed, const ReferenceMoments& reference, double tolerance) {
  ASSERT_EQ(computed.size(), reference.exact.size());
  double worst = 0.0;
  Eigen::Index worst_row = 0;
  for (Eigen::Index row = 0; row < computed.size(); ++row) {
    const double scale = std::max(std::abs(reference.exact(row)), reference.absolute(row));
    const double error = std::abs(computed(row) - reference.exact(row)) / scale;
    if (!(error <= worst)) {
      worst = error;
      worst_row = row;
    }
  }
  EXPECT_LE(worst, tolerance) << "monomial " << worst_row << ": computed " << computed(worst_row) << ", exact "
                              << reference.exact(worst_row);
}

}  // namespace altfem::test
