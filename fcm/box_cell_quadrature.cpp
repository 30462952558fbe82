#include "fcm/box_cell_quadrature.hpp"

#include <cmath>
#include <stdexcept>

#include "shared/element/reference_element.hpp"
#include "shared/quadrature/product_rules.hpp"
#include "shared/quadrature/reference_rules.hpp"

namespace altfem::fcm {

namespace {

// The cell's box from its corner nodes (VTK order: the first 8 nodes are the corners).
Eigen::AlignedBox3d cell_box(const VolumeMesh& grid, Eigen::Index cell) {
  Eigen::AlignedBox3d box;
  for (int a = 0; a < 8; ++a) box.extend(grid.nodes.row(grid.cells(cell, a)).transpose());
  const double tolerance = 1e-12 * box.diagonal().norm();
  for (int a = 0; a < 8; ++a) {
    const Eigen::Vector3d x = grid.nodes.row(grid.cells(cell, a)).transpose();
    for (int d = 0; d < 3; ++d)
      if (std::min(std::abs(x[d] - box.min()[d]), std::abs(x[d] - box.max()[d])) > tolerance)
        throw std::invalid_argument("box_cell_quadrature: cell " + std::to_string(cell) +
                                    " is not an axis-aligned box");
  }
  return box;
}

}  // namespace

CellQuadratureSource box_cell_quadrature(const VolumeMesh& grid, const Eigen::AlignedBox3d& body) {
  if (reference_element(grid.element_type).shape() != ElementShape::hexahedron)
    throw std::invalid_argument("box_cell_quadrature: needs a hexahedral grid");
  std::vector<Eigen::AlignedBox3d> boxes;
  for (Eigen::Index cell = 0; cell < grid.cells.rows(); ++cell) boxes.push_back(cell_box(grid, cell));
  // A box's tensor rule is already as small as exactness allows: nothing to simplify.
  return [boxes, body](int strength, RulePurpose) {
    const QuadratureRule tensor = tensor_hex_rule(strength);
    std::vector<CellQuadrature> cells(boxes.size());
    for (size_t c = 0; c < boxes.size(); ++c) {
      const Eigen::AlignedBox3d inside = boxes[c].intersection(body);
      const double fraction = inside.isEmpty() ? 0.0 : inside.volume() / boxes[c].volume();
      cells[c].volume_fraction = fraction;
      if (fraction <= 0 || fraction >= 1) continue;
      // [-1,1]³ → the intersection, expressed in the cell's reference coordinates:
      // ξ_cell = −1 + 2 (x − min) / size, weights scaled by the sub-box's share.
      const Eigen::Vector3d low = (2 * (inside.min() - boxes[c].min()).cwiseQuotient(boxes[c].sizes())).array() - 1;
      const Eigen::Vector3d high = (2 * (inside.max() - boxes[c].min()).cwiseQuotient(boxes[c].sizes())).array() - 1;
      QuadratureRule rule = tensor;
      for (Eigen::Index q = 0; q < rule.points.rows(); ++q)
        for (int d = 0; d < 3; ++d) rule.points(q, d) = low[d] + (high[d] - low[d]) * (tensor.points(q, d) + 1) / 2;
      rule.weights *= (high - low).prod() / 8;
      cells[c].rule = rule;
    }
    return cells;
  };
}

}  // namespace altfem::fcm
