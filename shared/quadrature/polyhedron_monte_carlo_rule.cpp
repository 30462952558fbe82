#include "shared/quadrature/polyhedron_monte_carlo_rule.hpp"

#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "shared/geometry/polyhedron_winding_number.hpp"

namespace altfem {

PolyhedronRule polyhedron_monte_carlo_rule(const Polyhedron& polyhedron, int count, std::uint64_t seed) {
  if (polyhedron.faces.empty()) throw std::invalid_argument("polyhedron_monte_carlo_rule: the polyhedron has no face");
  if (count < 1)
    throw std::invalid_argument("polyhedron_monte_carlo_rule: count must be >= 1, got " + std::to_string(count));
  const Eigen::Vector3d low = polyhedron.vertices.colwise().minCoeff().transpose();
  const Eigen::Vector3d high = polyhedron.vertices.colwise().maxCoeff().transpose();
  std::mt19937_64 generator(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Eigen::Vector3d> inside;
  for (int sample = 0; sample < count; ++sample) {
    Eigen::Vector3d x;
    for (int axis = 0; axis < 3; ++axis) x[axis] = low[axis] + unit(generator) * (high[axis] - low[axis]);
    if (winding_number(polyhedron, x) > 0.5) inside.push_back(x);
  }
  PolyhedronRule rule{Eigen::MatrixXd(static_cast<Eigen::Index>(inside.size()), 3),
                      Eigen::VectorXd::Constant(static_cast<Eigen::Index>(inside.size()), (high - low).prod() / count),
                      true};
  for (size_t q = 0; q < inside.size(); ++q) rule.points.row(static_cast<Eigen::Index>(q)) = inside[q].transpose();
  return rule;
}

}  // namespace altfem
