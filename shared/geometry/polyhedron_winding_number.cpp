#include "shared/geometry/polyhedron_winding_number.hpp"

#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

namespace altfem {

namespace {

// The solid angle of triangle (a, b, c) seen from the origin (Van Oosterom & Strackee 1983).
double solid_angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  const double numerator = a.dot(b.cross(c));
  const double denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
  return 2 * std::atan2(numerator, denominator);
}

}  // namespace

double fan_solid_angle(const Eigen::MatrixXd& points, const std::vector<int>& loop, const Eigen::Vector3d& x) {
  double total = 0;
  const Eigen::Vector3d first = points.row(loop[0]).transpose() - x;
  for (size_t k = 1; k + 1 < loop.size(); ++k)
    total += solid_angle(first, points.row(loop[k]).transpose() - x, points.row(loop[k + 1]).transpose() - x);
  return total;
}

double winding_number(const Polyhedron& polyhedron, const Eigen::Vector3d& x) {
  double total = 0;
  for (const auto& face : polyhedron.faces) total += fan_solid_angle(polyhedron.vertices, face, x);
  return total / (4 * std::numbers::pi);
}

}  // namespace altfem
