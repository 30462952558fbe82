#include "shared/simulation/nodal_basis.hpp"

#include <array>
#include <map>
#include <vector>

namespace altfem {

Eigen::VectorXd transfer_to_nodes(const Eigen::MatrixXd& nodes, const Eigen::MatrixXd& previous_nodes,
                                  const ElementBasisEvaluator& previous, const Eigen::VectorXd& field) {
  if (nodes.rows() == previous_nodes.rows() && nodes.cols() == previous_nodes.cols() && nodes == previous_nodes)
    return field;
  // Old nodes by exact position; a position held by several (fcm's node copies of
  // topology-aware cells) is left to the basis, which knows the pieces.
  std::map<std::array<double, 3>, Eigen::Index> old_node;
  std::map<std::array<double, 3>, int> copies;
  for (Eigen::Index node = 0; node < previous_nodes.rows(); ++node) {
    const std::array<double, 3> position{previous_nodes(node, 0), previous_nodes(node, 1), previous_nodes(node, 2)};
    old_node[position] = node;
    ++copies[position];
  }
  Eigen::VectorXd result(3 * nodes.rows());
  std::vector<Eigen::Index> moved;
  for (Eigen::Index node = 0; node < nodes.rows(); ++node) {
    const std::array<double, 3> position{nodes(node, 0), nodes(node, 1), nodes(node, 2)};
    const auto found = old_node.find(position);
    if (found != old_node.end() && copies[position] == 1) result.segment<3>(3 * node) = field.segment<3>(3 * found->second);
    else moved.push_back(node);
  }
  if (moved.empty()) return result;
  Eigen::MatrixXd points(static_cast<Eigen::Index>(moved.size()), 3);
  for (std::size_t i = 0; i < moved.size(); ++i) points.row(static_cast<Eigen::Index>(i)) = nodes.row(moved[i]);
  const Eigen::MatrixXd values = BasisEmbedding(previous, points).displacement(field);
  for (std::size_t i = 0; i < moved.size(); ++i)
    result.segment<3>(3 * moved[i]) = values.row(static_cast<Eigen::Index>(i)).transpose();
  return result;
}

Eigen::VectorXd interpolate_at_nodes(const Eigen::MatrixXd& nodes,
                                     const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& field) {
  Eigen::VectorXd values(3 * nodes.rows());
  for (Eigen::Index node = 0; node < nodes.rows(); ++node) values.segment<3>(3 * node) = field(nodes.row(node).transpose());
  return values;
}

void add_nodal_displacement(UnstructuredGrid& grid, const Eigen::VectorXd& displacement) {
  grid.point_data.emplace_back("displacement", Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(
                                                   displacement.data(), displacement.size() / 3, 3));
}

FieldQuadrature nodal_field_quadrature(std::shared_ptr<const TabulatedElements> elements, const Eigen::MatrixXd& nodes,
                                       int strength) {
  Eigen::MatrixXd points = nodal_quadrature_points(*elements, nodes);
  return {std::move(elements), std::move(points), strength};
}

}  // namespace altfem
