#include "shared/quadrature/polyhedron_subdivision_rule.hpp"

#include <stdexcept>
#include <string>
#include <vector>

#include "shared/geometry/polyhedron_winding_number.hpp"
#include "shared/quadrature/product_rules.hpp"

namespace altfem {

PolyhedronRule polyhedron_subdivision_rule(const Polyhedron& polyhedron, int strength, int levels) {
  if (polyhedron.faces.empty()) throw std::invalid_argument("polyhedron_subdivision_rule: the polyhedron has no face");
  // 2^10 boxes per axis are 10⁹ winding numbers: far beyond any use.
  if (levels < 0 || levels > 10)
    throw std::invalid_argument("polyhedron_subdivision_rule: levels must be in [0, 10], got " +
                                std::to_string(levels));
  const QuadratureRule box_rule = tensor_hex_rule(strength);  // on [-1,1]³
  const Eigen::Vector3d low = polyhedron.vertices.colwise().minCoeff().transpose();
  const Eigen::Vector3d high = polyhedron.vertices.colwise().maxCoeff().transpose();
  const int per_axis = 1 << levels;
  const Eigen::Vector3d size = (high - low) / per_axis;
  std::vector<Eigen::Vector3d> centres;
  for (int k = 0; k < per_axis; ++k)
    for (int j = 0; j < per_axis; ++j)
      for (int i = 0; i < per_axis; ++i) {
        const Eigen::Vector3d centre = low + size.cwiseProduct(Eigen::Vector3d(i + 0.5, j + 0.5, k + 0.5));
        if (winding_number(polyhedron, centre) > 0.5) centres.push_back(centre);
      }
  const Eigen::Index per_box = box_rule.weights.size();
  const double jacobian = size.prod() / 8;  // [-1,1]³ onto a box
  PolyhedronRule rule{Eigen::MatrixXd(static_cast<Eigen::Index>(centres.size()) * per_box, 3),
                      Eigen::VectorXd(static_cast<Eigen::Index>(centres.size()) * per_box), true};
  for (size_t b = 0; b < centres.size(); ++b)
    for (Eigen::Index q = 0; q < per_box; ++q) {
      const Eigen::Index row = static_cast<Eigen::Index>(b) * per_box + q;
      rule.points.row(row) = (centres[b] + 0.5 * size.cwiseProduct(box_rule.points.row(q).transpose())).transpose();
      rule.weights[row] = box_rule.weights[q] * jacobian;
    }
  return rule;
}

}  // namespace altfem
