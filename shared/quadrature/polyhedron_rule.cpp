#include "shared/quadrature/polyhedron_rule.hpp"

#include <Eigen/LU>
#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "shared/geometry/polyhedron_moments.hpp"
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
  const auto turns_left = [&](int a, int b, int c) { return (point(b) - point(a)).cross(point(c) - point(b)).dot(normal) > 0; };
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
  std::vector<std::array<int, 3>> triangles;
  while (remaining.size() > 3) {
    const auto m = remaining.size();
    bool clipped = false;
    for (size_t i = 0; i < m && !clipped; ++i) {
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
      for (size_t k = 1; k + 1 < remaining.size(); ++k) triangles.push_back({remaining[0], remaining[k], remaining[k + 1]});
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
  PolyhedronRule rule{Eigen::MatrixXd(triangles.size() * per_triangle, 3), Eigen::VectorXd(triangles.size() * per_triangle), true};
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

PolyhedronRule polyhedron_rule(const Polyhedron& polyhedron, int strength) {
  if (polyhedron.faces.empty()) throw std::invalid_argument("polyhedron_rule: the polyhedron has no face");
  const QuadratureRule tet = tet_rule(strength);
  // The centroid as apex: it sees the whole cell whenever the cell is convex, and the
  // mean of the vertices can sit on a re-entrant edge (an L-shaped cell's is its corner).
  const Eigen::VectorXd first_moments = polyhedron_moments(polyhedron, 1);
  const Eigen::Vector3d apex = first_moments.segment<3>(1) / first_moments[0];
  const double size = (polyhedron.vertices.colwise().maxCoeff() - polyhedron.vertices.colwise().minCoeff()).norm();
  std::vector<Eigen::Matrix3d> jacobians;
  for (const auto& face : polyhedron.faces)
    for (const auto& triangle : triangulate_face(polyhedron.vertices, face)) {
      Eigen::Matrix3d jacobian;
      for (int c = 0; c < 3; ++c) jacobian.col(c) = polyhedron.vertices.row(face[triangle[c]]).transpose() - apex;
      // A face through the apex spans no volume (round-off aside).
      if (std::abs(jacobian.determinant()) > 1e-13 * size * size * size) jacobians.push_back(jacobian);
    }
  const auto per_tet = tet.weights.size();
  PolyhedronRule rule{Eigen::MatrixXd(jacobians.size() * per_tet, 3), Eigen::VectorXd(jacobians.size() * per_tet), true};
  for (size_t t = 0; t < jacobians.size(); ++t) {
    const double determinant = jacobians[t].determinant();  // > 0 when the face is seen from inside
    for (Eigen::Index q = 0; q < per_tet; ++q) {
      const Eigen::Index row = static_cast<Eigen::Index>(t) * per_tet + q;
      rule.points.row(row) = (apex + jacobians[t] * tet.points.row(q).transpose()).transpose();
      rule.weights[row] = tet.weights[q] * determinant;
    }
    rule.positive = rule.positive && determinant > 0;
  }
  return rule;
}

}  // namespace altfem
