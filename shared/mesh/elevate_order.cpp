#include "shared/mesh/elevate_order.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

#include "shared/element/reference_element.hpp"

namespace altfem {

VolumeMesh elevate_order(const VolumeMesh& linear_mesh, ElementType type) {
  const ElementShape shape = element_shape(type);
  const ElementType linear_type = shape == ElementShape::tetrahedron ? ElementType::tet4 : ElementType::hex8;
  if (linear_mesh.element_type != linear_type)
    throw std::invalid_argument("elevate_order: a " + std::string(element_name(type)) + " mesh needs a " +
                                std::string(element_name(linear_type)) + " mesh to start from");
  if (type == linear_type) return linear_mesh;

  const ReferenceElement& linear = reference_element(linear_type);
  const ReferenceElement& target = reference_element(type);
  const int corners = linear.node_count();
  const int nodes_per_cell = target.node_count();

  // Corner weights of every target node: N_corner(ξ_node) of the linear element;
  // weights are multiples of 1/24 for every supported type, so they key exactly.
  std::vector<std::vector<std::pair<int, int>>> weights(nodes_per_cell);
  Eigen::VectorXd values(corners);
  for (int node = 0; node < nodes_per_cell; ++node) {
    linear.evaluate(target.nodes().row(node).transpose(), values);
    for (int corner = 0; corner < corners; ++corner) {
      const long scaled = std::lround(values[corner] * 72.0);
      if (scaled != 0) weights[node].push_back({corner, static_cast<int>(scaled)});
    }
  }

  VolumeMesh mesh;
  mesh.element_type = type;
  mesh.cells.resize(linear_mesh.cells.rows(), nodes_per_cell);
  std::vector<Eigen::Vector3d> positions;
  positions.reserve(static_cast<size_t>(linear_mesh.nodes.rows()) * 4);
  for (Eigen::Index i = 0; i < linear_mesh.nodes.rows(); ++i) positions.push_back(linear_mesh.nodes.row(i).transpose());
  std::map<std::vector<std::pair<int, int>>, int> created;
  std::vector<std::pair<int, int>> key;
  for (Eigen::Index cell = 0; cell < linear_mesh.cells.rows(); ++cell) {
    for (int node = 0; node < nodes_per_cell; ++node) {
      if (node < corners) {
        mesh.cells(cell, node) = linear_mesh.cells(cell, node);
        continue;
      }
      key.clear();
      Eigen::Vector3d position = Eigen::Vector3d::Zero();
      for (auto [corner, weight] : weights[node]) {
        const int vertex = linear_mesh.cells(cell, corner);
        key.push_back({vertex, weight});
        position += (weight / 72.0) * linear_mesh.nodes.row(vertex).transpose();
      }
      std::sort(key.begin(), key.end());
      auto [entry, inserted] = created.try_emplace(key, static_cast<int>(positions.size()));
      if (inserted) positions.push_back(position);
      mesh.cells(cell, node) = entry->second;
    }
  }
  mesh.nodes.resize(static_cast<Eigen::Index>(positions.size()), 3);
  for (size_t i = 0; i < positions.size(); ++i) mesh.nodes.row(static_cast<Eigen::Index>(i)) = positions[i].transpose();
  return mesh;
}

}  // namespace altfem
