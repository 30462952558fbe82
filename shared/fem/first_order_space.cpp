#include "shared/fem/first_order_space.hpp"

#include "shared/element/reference_element.hpp"
#include "shared/element/reference_nodes.hpp"

namespace altfem {

namespace {

ElementType first_order_type(ElementType type) {
  return element_shape(type) == ElementShape::tetrahedron ? ElementType::tet4 : ElementType::hex8;
}

}  // namespace

CoarseSpace first_order_space(const VolumeMesh& mesh, const NodeConstraints* constraints) {
  CoarseSpace space;
  const ElementType coarse_type = first_order_type(mesh.element_type);
  if (coarse_type == mesh.element_type || (constraints && !constraints->empty())) return space;
  const int corners = element_corner_count(mesh.element_type);
  const auto node_count = static_cast<int>(mesh.nodes.rows());

  // Coarse functions numbered in order of their nodes.
  std::vector<int> coarse_of_node(static_cast<size_t>(node_count), -1);
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell)
    for (int corner = 0; corner < corners; ++corner) coarse_of_node[mesh.cells(cell, corner)] = 0;
  for (int node = 0; node < node_count; ++node)
    if (coarse_of_node[node] == 0) {
      coarse_of_node[node] = static_cast<int>(space.fine_function.size());
      space.fine_function.push_back(node);
    }

  // The first-order basis at each reference node: #nodes per cell × #corners.
  const Eigen::MatrixXd nodes = reference_nodes(mesh.element_type);
  const ReferenceElement& coarse_element = reference_element(coarse_type);
  Eigen::MatrixXd corner_values(nodes.rows(), corners);
  Eigen::VectorXd values(corners);
  for (Eigen::Index node = 0; node < nodes.rows(); ++node) {
    coarse_element.evaluate(nodes.row(node).transpose(), values);
    corner_values.row(node) = values.transpose();
  }

  // Each node's row once, from the first cell that holds it; entries of round-off size
  // (a corner's value at the opposite corner) left out.
  std::vector<char> done(static_cast<size_t>(node_count), 0);
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<size_t>(node_count) * 4);
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell)
    for (Eigen::Index local = 0; local < mesh.cells.cols(); ++local) {
      const int node = mesh.cells(cell, local);
      if (done[node]) continue;
      done[node] = 1;
      for (int corner = 0; corner < corners; ++corner)
        if (std::abs(corner_values(local, corner)) > 1e-14)
          entries.emplace_back(node, coarse_of_node[mesh.cells(cell, corner)], corner_values(local, corner));
    }
  space.prolongation.resize(node_count, static_cast<Eigen::Index>(space.fine_function.size()));
  space.prolongation.setFromTriplets(entries.begin(), entries.end());
  return space;
}

}  // namespace altfem
