#include "shared/simulation/nodal_basis.hpp"

#include <array>
#include <map>
#include <vector>

namespace altfem {

Eigen::MatrixXd transfer_to_nodes(const Eigen::MatrixXd& nodes, const Eigen::MatrixXd& previous_nodes,
                                  const ElementBasisEvaluator& previous, const Eigen::MatrixXd& fields) {
  if (nodes.rows() == previous_nodes.rows() && nodes.cols() == previous_nodes.cols() && nodes == previous_nodes)
    return fields;
  // Old nodes by exact position, −1 where several share one (fcm's node copies of
  // topology-aware cells): those are left to the basis, which knows the pieces.
  std::map<std::array<double, 3>, Eigen::Index> old_node;
  for (Eigen::Index node = 0; node < previous_nodes.rows(); ++node) {
    const auto [entry, inserted] = old_node.emplace(
        std::array<double, 3>{previous_nodes(node, 0), previous_nodes(node, 1), previous_nodes(node, 2)}, node);
    if (!inserted) entry->second = -1;
  }
  Eigen::MatrixXd result(3 * nodes.rows(), fields.cols());
  std::vector<Eigen::Index> moved;
  for (Eigen::Index node = 0; node < nodes.rows(); ++node) {
    // A node at its old index and position is that node (a cut keeps the old numbering):
    // this tells apart the copies of a node an earlier cut duplicated, one per side.
    if (node < previous_nodes.rows() && nodes.row(node) == previous_nodes.row(node)) {
      result.middleRows<3>(3 * node) = fields.middleRows<3>(3 * node);
      continue;
    }
    const auto found = old_node.find({nodes(node, 0), nodes(node, 1), nodes(node, 2)});
    if (found != old_node.end() && found->second >= 0)
      result.middleRows<3>(3 * node) = fields.middleRows<3>(3 * found->second);
    else moved.push_back(node);
  }
  if (moved.empty()) return result;
  Eigen::MatrixXd points(static_cast<Eigen::Index>(moved.size()), 3);
  for (std::size_t i = 0; i < moved.size(); ++i) points.row(static_cast<Eigen::Index>(i)) = nodes.row(moved[i]);
  const BasisEmbedding embedding(previous, points);
  for (Eigen::Index column = 0; column < fields.cols(); ++column) {
    const Eigen::MatrixXd values = embedding.displacement(fields.col(column));
    for (std::size_t i = 0; i < moved.size(); ++i)
      result.block<3, 1>(3 * moved[i], column) = values.row(static_cast<Eigen::Index>(i)).transpose();
  }
  return result;
}

Eigen::VectorXd interpolate_at_nodes(const Eigen::MatrixXd& nodes,
                                     const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& field) {
  Eigen::VectorXd values(3 * nodes.rows());
  for (Eigen::Index node = 0; node < nodes.rows(); ++node)
    values.segment<3>(3 * node) = field(nodes.row(node).transpose());
  return values;
}

void add_nodal_displacement(UnstructuredGrid& grid, const Eigen::VectorXd& displacement) {
  grid.point_data.emplace_back("displacement",
                               Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(
                                   displacement.data(), displacement.size() / 3, 3));
}

FieldQuadrature nodal_field_quadrature(std::shared_ptr<const TabulatedElements> elements, const Eigen::MatrixXd& nodes,
                                       int strength) {
  Eigen::MatrixXd points = nodal_quadrature_points(*elements, nodes);
  return {std::move(elements), std::move(points), strength};
}

}  // namespace altfem
