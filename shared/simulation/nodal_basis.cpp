#include "shared/simulation/nodal_basis.hpp"

namespace altfem {

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

nlohmann::json embedding_facts(const SurfaceMesh& surface, const BasisEmbedding& embedding) {
  return {{"surface_vertices", surface.vertices.rows()},
          {"surface_vertices_outside_mesh", embedding.outside_count()},
          {"max_outside_distance", embedding.max_outside_distance()}};
}

}  // namespace altfem
