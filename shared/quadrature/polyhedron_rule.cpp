#include "shared/quadrature/polyhedron_rule.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <vector>

#include "shared/geometry/monomial_index.hpp"
#include "shared/geometry/polyhedron_moments.hpp"
#include "shared/quadrature/basic_feasible_point.hpp"
#include "shared/quadrature/polyhedron_kernel_point.hpp"
#include "shared/quadrature/reference_rules.hpp"

namespace altfem {

// Unlike a fan, every triangle keeps the face's orientation, so a cell star-shaped about
// the apex gives only positive tetrahedra.
std::vector<std::array<int, 3>> triangulate_face(const Eigen::MatrixXd& vertices, const std::vector<int>& face) {
  const auto n = static_cast<int>(face.size());
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // Newell's normal
  for (int k = 0; k < n; ++k)
    normal += Eigen::Vector3d(vertices.row(face[k])).cross(Eigen::Vector3d(vertices.row(face[(k + 1) % n])));
  const auto point = [&](int k) { return Eigen::Vector3d(vertices.row(face[k])); };
  const auto turns_left = [&](int a, int b, int c) {
    return (point(b) - point(a)).cross(point(c) - point(b)).dot(normal) > 0;
  };
  // p inside or on the boundary of triangle (a, b, c): a vertex on the would-be diagonal
  // (an L-shaped face's re-entrant corner) must block the ear too.
  const auto inside = [&](int p, int a, int b, int c) {
    const Eigen::Vector3d x = point(p);
    return (point(b) - point(a)).cross(x - point(a)).dot(normal) >= 0 &&
           (point(c) - point(b)).cross(x - point(b)).dot(normal) >= 0 &&
           (point(a) - point(c)).cross(x - point(c)).dot(normal) >= 0;
  };
  std::vector<int> remaining(n);
  for (int k = 0; k < n; ++k) remaining[k] = k;
  // Ears are tried tip first in lexicographic order of the tip's position, not in loop
  // order: the ears of a loop and of its reverse are the same, so both orientations of a
  // mesh face (its two cells) get the same triangles and, with a symmetric triangle rule,
  // the same points. The harmonic cells' face integrals then cancel to round-off between
  // neighbours (the patch test, harmonic_tabulation.hpp), where a loop-order choice left
  // 1e-4 of the forces on the interior nodes of a sliced mesh.
  const auto before = [&](size_t i, size_t j) {
    const Eigen::Vector3d p = point(remaining[i]), q = point(remaining[j]);
    return std::lexicographical_compare(p.begin(), p.end(), q.begin(), q.end());
  };
  std::vector<size_t> order;
  std::vector<std::array<int, 3>> triangles;
  while (remaining.size() > 3) {
    const auto m = remaining.size();
    order.resize(m);
    for (size_t i = 0; i < m; ++i) order[i] = i;
    std::sort(order.begin(), order.end(), before);
    bool clipped = false;
    for (size_t tried = 0; tried < m && !clipped; ++tried) {
      const size_t i = order[tried];
      const int a = remaining[(i + m - 1) % m], b = remaining[i], c = remaining[(i + 1) % m];
      if (!turns_left(a, b, c)) continue;
      bool ear = true;
      for (int other : remaining)
        if (other != a && other != b && other != c && point(other) != point(a) && point(other) != point(b) &&
            point(other) != point(c) && inside(other, a, b, c))
          ear = false;
      if (!ear) continue;
      triangles.push_back({a, b, c});
      remaining.erase(remaining.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
    }
    if (!clipped) {  // collinear or degenerate remains: fan them (signed, still exact)
      for (size_t k = 1; k + 1 < remaining.size(); ++k)
        triangles.push_back({remaining[0], remaining[k], remaining[k + 1]});
      return triangles;
    }
  }
  triangles.push_back({remaining[0], remaining[1], remaining[2]});
  return triangles;
}

PolyhedronRule polygon_rule(const Eigen::MatrixXd& polygon, int strength) {
  const QuadratureRule triangle = triangle_rule(strength);
  std::vector<int> face(static_cast<size_t>(polygon.rows()));
  for (size_t k = 0; k < face.size(); ++k) face[k] = static_cast<int>(k);
  const auto triangles = triangulate_face(polygon, face);
  const auto per_triangle = triangle.weights.size();
  PolyhedronRule rule{Eigen::MatrixXd(triangles.size() * per_triangle, 3),
                      Eigen::VectorXd(triangles.size() * per_triangle), true};
  for (size_t t = 0; t < triangles.size(); ++t) {
    const Eigen::Vector3d a = polygon.row(triangles[t][0]).transpose(), b = polygon.row(triangles[t][1]).transpose(),
                          c = polygon.row(triangles[t][2]).transpose();
    const double area_ratio = (b - a).cross(c - a).norm();  // the unit triangle has area ½
    for (Eigen::Index q = 0; q < per_triangle; ++q) {
      const Eigen::Index row = static_cast<Eigen::Index>(t) * per_triangle + q;
      rule.points.row(row) = (a + triangle.points(q, 0) * (b - a) + triangle.points(q, 1) * (c - a)).transpose();
      rule.weights[row] = triangle.weights[q] * area_ratio;
    }
  }
  return rule;
}

namespace {

// A positive rule for a polyhedron that is not star-shaped: candidate points are those of
// the signed cone rule of strength 2·strength + 2 (strength + 2 left the moment equations
// of a U-prism infeasible at strength 5) that lie inside the cell (inverted tetrahedra
// reach outside it; x is inside when the signs of the cone tetrahedra holding it add up
// to 1), and weights w ≥ 0 solve the moment equations Σ_q w_q m_α(x_q) = ∫_P m_α for
// every monomial of degree ≤ strength (a basic feasible point, Clp: at most that many
// points, as the simplified rules of Longva et al. 2020 §4.4). Nullopt when infeasible.
//
// A cut cell of a detailed surface has thousands of cone tetrahedra, so testing every
// candidate (one pass over the tetrahedra each) and handing all of them to the LP cost
// minutes per cell. Far fewer suffice: the candidates are visited in an order that strides
// across all tetrahedra, and the LP first gets the first 20 × #moments inside ones, then
// twice as many, until it is feasible or every candidate has been offered.
//
// Such a rule has at most #moments points (10 at strength 2), too few for a basis with
// more functions than that (an MFS cell of a sliced surface has hundreds of nodes, its
// stiffness then rank 3 × #points: hourglass modes). With `minimum_points`, candidates
// are gathered until there are that many, and the weights are spread over all of them
// (spread_feasible_point: each at least t times its cone weight, t maximal).
std::optional<PolyhedronRule> positive_moment_rule(const Polyhedron& polyhedron, int strength,
                                                   const Eigen::Vector3d& apex,
                                                   const std::vector<Eigen::Matrix3d>& jacobians, double size,
                                                   int minimum_points) {
  const QuadratureRule tet = tet_rule(2 * strength + 2);
  std::vector<Eigen::Matrix3d> inverses;
  std::vector<int> signs;
  for (const Eigen::Matrix3d& jacobian : jacobians) {
    inverses.push_back(jacobian.inverse());
    signs.push_back(jacobian.determinant() > 0 ? 1 : -1);
  }
  const auto inside = [&](const Eigen::Vector3d& x) {
    int winding = 0;
    for (size_t t = 0; t < inverses.size(); ++t) {
      const Eigen::Vector3d lambda = inverses[t] * (x - apex);
      if (lambda.minCoeff() >= 0 && lambda.sum() <= 1) winding += signs[t];
    }
    return winding == 1;
  };
  const Eigen::Matrix<int, Eigen::Dynamic, 3> exponents = monomial_exponents(strength);
  const Eigen::VectorXd moments = polyhedron_moments(polyhedron, strength, apex, size);
  const auto per_tet = static_cast<long>(tet.weights.size());
  const long candidate_count = static_cast<long>(jacobians.size()) * per_tet;
  // A stride coprime to the count visits every candidate once, hopping across tetrahedra.
  long stride = 7919;
  while (std::gcd(stride, candidate_count) != 1) stride += 2;
  std::vector<Eigen::Vector3d> candidates;
  std::vector<double> cone_weights;                // each candidate's |weight| in the signed cone rule
  Eigen::MatrixXd monomials(exponents.rows(), 0);  // one column per candidate, kept across batches
  long visited = 0;
  for (auto batch = static_cast<size_t>(std::max<Eigen::Index>(20 * exponents.rows(), minimum_points));; batch *= 2) {
    const size_t evaluated = candidates.size();
    for (; visited < candidate_count && candidates.size() < batch; ++visited) {
      const long index = (visited * stride) % candidate_count;
      const Eigen::Vector3d x = apex + jacobians[index / per_tet] * tet.points.row(index % per_tet).transpose();
      if (!inside(x)) continue;
      candidates.push_back(x);
      cone_weights.push_back(std::abs(tet.weights[index % per_tet] * jacobians[index / per_tet].determinant()));
    }
    // Monomials about the apex scaled by the size, so every entry is O(1): only the new
    // candidates' columns are evaluated.
    monomials.conservativeResize(Eigen::NoChange, static_cast<Eigen::Index>(candidates.size()));
    for (size_t q = evaluated; q < candidates.size(); ++q) {
      const Eigen::Vector3d x = (candidates[q] - apex) / size;
      for (Eigen::Index i = 0; i < exponents.rows(); ++i)
        monomials(i, static_cast<Eigen::Index>(q)) =
            std::pow(x.x(), exponents(i, 0)) * std::pow(x.y(), exponents(i, 1)) * std::pow(x.z(), exponents(i, 2));
    }
    const auto exact = [&](const std::optional<Eigen::VectorXd>& weights) {
      return weights && (monomials * *weights - moments).cwiseAbs().maxCoeff() <= 1e-10 * moments[0];
    };
    // A spread rule that Clp does not find exact gets more candidates; the basic rule is
    // the last resort.
    const bool exhausted = visited == candidate_count;
    std::optional<Eigen::VectorXd> weights;
    if (minimum_points > 0)
      weights = spread_feasible_point(monomials, moments,
                                      Eigen::Map<const Eigen::VectorXd>(cone_weights.data(), cone_weights.size()));
    if (!exact(weights) && (minimum_points == 0 || exhausted)) weights = basic_feasible_point(monomials, moments);
    if (exact(weights)) {
      PolyhedronRule rule;
      const auto count = static_cast<Eigen::Index>((weights->array() > 0).count());
      rule.points.resize(count, 3);
      rule.weights.resize(count);
      for (Eigen::Index q = 0, row = 0; q < weights->size(); ++q)
        if ((*weights)[q] > 0) {
          rule.points.row(row) = candidates[q].transpose();
          rule.weights[row++] = (*weights)[q];
        }
      return rule;
    }
    if (exhausted) return std::nullopt;
  }
}

}  // namespace

PolyhedronRule polyhedron_rule(const Polyhedron& polyhedron, int strength, int minimum_points) {
  if (polyhedron.faces.empty()) throw std::invalid_argument("polyhedron_rule: the polyhedron has no face");
  const QuadratureRule tet = tet_rule(strength);
  // The centroid as apex: it sees the whole cell whenever the cell is convex, and the
  // mean of the vertices can sit on a re-entrant edge (an L-shaped cell's is its corner).
  // When it does not see every face from inside (inverted tetrahedra: negative weights,
  // which can make a lumped mass negative), the kernel's centre does if the cell is
  // star-shaped at all.
  const Eigen::VectorXd first_moments = polyhedron_moments(polyhedron, 1);
  Eigen::Vector3d apex = first_moments.segment<3>(1) / first_moments[0];
  const double size = (polyhedron.vertices.colwise().maxCoeff() - polyhedron.vertices.colwise().minCoeff()).norm();
  const double degenerate = 1e-13 * size * size * size;
  std::vector<Eigen::Matrix3d> jacobians;
  const auto cone = [&] {
    jacobians.clear();
    bool positive = true;
    for (const auto& face : polyhedron.faces)
      for (const auto& triangle : triangulate_face(polyhedron.vertices, face)) {
        Eigen::Matrix3d jacobian;
        for (int c = 0; c < 3; ++c) jacobian.col(c) = polyhedron.vertices.row(face[triangle[c]]).transpose() - apex;
        // A face through the apex spans no volume (round-off aside).
        const double determinant = jacobian.determinant();
        if (std::abs(determinant) > degenerate) jacobians.push_back(jacobian);
        positive = positive && determinant > -degenerate;
      }
    return positive;
  };
  if (!cone())
    if (const auto kernel_point = polyhedron_kernel_point(polyhedron)) {
      apex = *kernel_point;
      cone();
    }
  const auto per_tet = tet.weights.size();
  PolyhedronRule rule{Eigen::MatrixXd(jacobians.size() * per_tet, 3), Eigen::VectorXd(jacobians.size() * per_tet),
                      true};
  for (size_t t = 0; t < jacobians.size(); ++t) {
    const double determinant = jacobians[t].determinant();  // > 0 when the face is seen from inside
    for (Eigen::Index q = 0; q < per_tet; ++q) {
      const Eigen::Index row = static_cast<Eigen::Index>(t) * per_tet + q;
      rule.points.row(row) = (apex + jacobians[t] * tet.points.row(q).transpose()).transpose();
      rule.weights[row] = tet.weights[q] * determinant;
    }
    rule.positive = rule.positive && determinant > 0;
  }
  if (!rule.positive)
    if (auto positive = positive_moment_rule(polyhedron, strength, apex, jacobians, size, minimum_points))
      return std::move(*positive);
  return rule;
}

PolyhedronRule simplified_polyhedron_rule(const Polyhedron& polyhedron, int strength,
                                          std::optional<SimplificationMethod> method, int minimum_points) {
  PolyhedronRule rule = polyhedron_rule(polyhedron, strength, minimum_points);
  if (!method || !rule.positive) return rule;  // no positive-weight simplifier starts from negative weights
  SimplificationOptions options;
  options.degree = strength;
  options.method = *method;
  SimplificationResult simplified = simplify_quadrature({rule.points, rule.weights, strength}, options);
  if (!simplified.simplified) return rule;
  rule.points = std::move(simplified.rule.points);
  rule.weights = std::move(simplified.rule.weights);
  return rule;
}

}  // namespace altfem
