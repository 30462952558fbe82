#include "shared/fem/first_order_space.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <utility>

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
  if (coarse_type == mesh.element_type) return space;
  const int corners = element_corner_count(mesh.element_type);
  const auto node_count = static_cast<int>(mesh.nodes.rows());
  const bool hanging = constraints && !constraints->empty();
  const int free_nodes = hanging ? constraints->free_nodes : node_count;

  // A node that some cell holds other than as a corner (a coarser cell's mid-edge node where
  // finer cells have a corner, on a refined grid) takes that cell's first-order values, as it
  // would hang on a first-order grid; the other free corners are the coarse functions,
  // numbered in order of their nodes.
  constexpr int unused = -1, corner_only = -2;
  std::vector<Eigen::Index> holder(static_cast<size_t>(node_count), unused);  // cell · #nodes per cell + local
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell)
    for (Eigen::Index local = 0; local < mesh.cells.cols(); ++local) {
      Eigen::Index& held = holder[mesh.cells(cell, local)];
      if (local >= corners && held < 0) held = cell * mesh.cells.cols() + local;
      else if (local < corners && held == unused) held = corner_only;
    }
  std::vector<int> coarse_of_node(static_cast<size_t>(node_count), -1);
  for (int node = 0; node < free_nodes; ++node)
    if (holder[node] == corner_only) {
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

  // Each node's values as a combination of coarse functions: its own; a hanging node its
  // masters' (the constraint's weights); any other node its holder cell's first-order
  // values from its corners, which may hang on a coarser cell in turn (2:1 balance keeps
  // the chain short). Entries of round-off size (a corner's value at the opposite corner)
  // are left out.
  using Combination = std::vector<std::pair<int, double>>;
  std::vector<Combination> combination(static_cast<size_t>(node_count));
  std::vector<char> state(static_cast<size_t>(node_count), 0);  // 1: being formed, 2: formed
  const std::function<const Combination&(int)> combination_of = [&](int node) -> const Combination& {
    Combination& result = combination[node];
    if (state[node] == 2) return result;
    if (state[node] == 1) throw std::logic_error("first_order_space: hanging nodes constrained in a cycle");
    state[node] = 1;
    const auto add = [&](int other, double weight) {
      for (const auto& [coarse, value] : combination_of(other)) result.emplace_back(coarse, weight * value);
    };
    if (coarse_of_node[node] >= 0) {
      result.emplace_back(coarse_of_node[node], 1.0);
    } else if (node >= free_nodes) {
      const int index = node - free_nodes;
      for (size_t k = 0; k < constraints->masters[index].size(); ++k)
        add(constraints->masters[index][k], constraints->weights[index][k]);
    } else if (holder[node] >= 0) {
      const Eigen::Index cell = holder[node] / mesh.cells.cols(), local = holder[node] % mesh.cells.cols();
      for (int corner = 0; corner < corners; ++corner)
        if (std::abs(corner_values(local, corner)) > 1e-14) add(mesh.cells(cell, corner), corner_values(local, corner));
    }
    std::sort(result.begin(), result.end());
    Combination merged;
    for (const auto& [coarse, value] : result)
      if (!merged.empty() && merged.back().first == coarse) merged.back().second += value;
      else merged.emplace_back(coarse, value);
    std::erase_if(merged, [](const std::pair<int, double>& entry) { return std::abs(entry.second) <= 1e-14; });
    result = std::move(merged);
    state[node] = 2;
    return result;
  };

  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<size_t>(free_nodes) * 4);
  for (int node = 0; node < free_nodes; ++node)
    for (const auto& [coarse, value] : combination_of(node)) entries.emplace_back(node, coarse, value);
  space.prolongation.resize(free_nodes, static_cast<Eigen::Index>(space.fine_function.size()));
  space.prolongation.setFromTriplets(entries.begin(), entries.end());
  return space;
}

}  // namespace altfem
