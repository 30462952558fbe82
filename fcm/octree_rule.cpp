#include "fcm/octree_rule.hpp"

#include <stdexcept>
#include <vector>

#include "shared/element/geometry_map.hpp"
#include "shared/element/reference_element.hpp"
#include "shared/quadrature/product_rules.hpp"

namespace altfem::fcm {
namespace {

struct Octant {
  Eigen::Vector3d centre;  ///< reference coordinates
  double half;             ///< half edge length in reference coordinates
  int level;
};

}  // namespace

QuadratureRule octree_rule(const CellGeometry& cell, const AnalyticShape& shape, const OctreeOptions& options) {
  if (element_shape(cell.type()) != ElementShape::hexahedron) {
    throw std::invalid_argument("octree_rule: hexahedral cells only");
  }
  const ReferenceElement& corner_map = reference_element(ElementType::hex8);
  const QuadratureRule leaf = tensor_hex_rule(options.leaf_order);  // on [-1,1]³
  const auto physical = [&](const Eigen::Vector3d& xi) { return map_to_physical(corner_map, cell.corners(), xi); };
  std::vector<Eigen::RowVector3d> points;
  std::vector<double> weights;
  const auto add_leaf = [&](const Octant& octant, bool filter) {
    const double scale = octant.half * octant.half * octant.half;
    for (Eigen::Index q = 0; q < leaf.points.rows(); ++q) {
      const Eigen::Vector3d xi = octant.centre + octant.half * leaf.points.row(q).transpose();
      if (filter && !shape.contains(physical(xi))) continue;
      points.push_back(xi.transpose());
      weights.push_back(scale * leaf.weights(q));
    }
  };
  std::vector<Octant> stack{{Eigen::Vector3d::Zero(), 1.0, 0}};
  while (!stack.empty()) {
    const Octant octant = stack.back();
    stack.pop_back();
    const Eigen::Vector3d centre = physical(octant.centre);
    double radius = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3d offset(corner & 1 ? 1.0 : -1.0, corner & 2 ? 1.0 : -1.0, corner & 4 ? 1.0 : -1.0);
      radius = std::max(radius, (physical(octant.centre + octant.half * offset) - centre).norm());
    }
    const double level = shape.level_set(centre);
    if (level >= radius) continue;  // entirely outside
    if (level <= -radius) {         // entirely inside
      add_leaf(octant, false);
      continue;
    }
    if (octant.level >= options.depth) {
      add_leaf(octant, true);
      continue;
    }
    for (int child = 0; child < 8; ++child) {
      const Eigen::Vector3d offset(child & 1 ? 0.5 : -0.5, child & 2 ? 0.5 : -0.5, child & 4 ? 0.5 : -0.5);
      stack.push_back({octant.centre + octant.half * offset, 0.5 * octant.half, octant.level + 1});
    }
  }
  QuadratureRule rule;
  rule.points.resize(static_cast<Eigen::Index>(points.size()), 3);
  rule.weights.resize(static_cast<Eigen::Index>(weights.size()));
  for (std::size_t i = 0; i < points.size(); ++i) {
    rule.points.row(i) = points[i];
    rule.weights(i) = weights[i];
  }
  rule.strength = options.leaf_order;
  return rule;
}

}  // namespace altfem::fcm
