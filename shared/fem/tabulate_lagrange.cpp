#include "shared/fem/tabulate_lagrange.hpp"

#include <Eigen/LU>
#include <array>
#include <atomic>
#include <string>
#include <vector>

#include "shared/assembly/tabulated_here.hpp"
#include "shared/common/error.hpp"
#include "shared/element/reference_element.hpp"
#include "shared/fem/constrain_lagrange_elements.hpp"
#include "shared/quadrature/reference_rules.hpp"

namespace altfem {

namespace {

// Basis values (#points × #nodes) and reference gradients (per direction j, #points ×
// #nodes: row q holds ∂N/∂ξ_j at point q) of a rule, as evaluate_at gives them (a matrix
// per point was an allocation per point of every cut cell).
struct ReferenceTable {
  Eigen::MatrixXd values;
  std::array<Eigen::MatrixXd, 3> gradients;
};

ReferenceTable reference_table(const ReferenceElement& element, const QuadratureRule& rule) {
  ReferenceTable table;
  element.evaluate_at(rule.points, table.values);
  element.evaluate_gradients_at(rule.points, table.gradients);
  return table;
}

}  // namespace

TabulatedElements tabulate_lagrange(const VolumeMesh& mesh, const LagrangeCellRules& rules, const TabulatedHere& here) {
  const ReferenceElement& element = reference_element(mesh.element_type);
  const int n = element.node_count();
  const int cells = static_cast<int>(mesh.cells.rows());
  // The standard rule's reference table serves every cell that has no rule of its own.
  const ReferenceTable standard = reference_table(element, rules.standard);

  // Physical data per cell, computed in parallel, then appended in cell order.
  std::vector<Eigen::VectorXd> weights(cells);
  std::vector<Eigen::MatrixXd> gradients(cells);
  std::vector<Eigen::MatrixXd> custom_values(cells);
  std::atomic<int> failed_cell{-1};
  std::atomic<int> failed_point{-1};
  const std::vector<char> held = tabulated_here(here, cells);
#pragma omp parallel for schedule(dynamic, 16)
  for (int cell = 0; cell < cells; ++cell) {
    if (!held[cell]) continue;
    const auto custom = rules.custom.find(cell);
    const bool own_rule = custom != rules.custom.end();
    const QuadratureRule& rule = own_rule ? custom->second : rules.standard;
    ReferenceTable own;
    if (own_rule) {
      own = reference_table(element, rule);
      custom_values[cell] = own.values;
    }
    const ReferenceTable& table = own_rule ? own : standard;
    const auto points = static_cast<int>(rule.weights.size());
    Eigen::MatrixXd nodes(n, 3), reference_gradients(n, 3);
    for (int a = 0; a < n; ++a) nodes.row(a) = mesh.nodes.row(mesh.cells(cell, a));
    weights[cell].resize(points);
    gradients[cell].resize(static_cast<Eigen::Index>(points) * n, 3);
    // Coefficient-wise products: these are 3 × #nodes × 3 at every point, which Eigen would
    // otherwise hand to its blocked matrix product, packing both operands each time.
    for (int q = 0; q < points; ++q) {
      for (int j = 0; j < 3; ++j) reference_gradients.col(j) = table.gradients[j].row(q).transpose();
      const Eigen::Matrix3d jacobian = nodes.transpose().lazyProduct(reference_gradients);  // ∂x_i/∂ξ_j
      const double determinant = jacobian.determinant();
      if (!(determinant > 0)) {
        int expected = -1;
        if (failed_cell.compare_exchange_strong(expected, cell)) failed_point = q;
        break;
      }
      weights[cell][q] = rule.weights[q] * determinant;
      gradients[cell].middleRows(static_cast<Eigen::Index>(q) * n, n) =
          reference_gradients.lazyProduct(jacobian.inverse());
    }
  }
  if (failed_cell >= 0)
    throw NumericalError("cell " + std::to_string(failed_cell.load()) + ": det J <= 0 at quadrature point " +
                         std::to_string(failed_point.load()) + " (inverted or degenerate " +
                         std::string(element_name(mesh.element_type)) + ")");

  long long point_total = 0;
  for (const auto& cell_weights : weights) point_total += cell_weights.size();
  TabulatedElements tabulated;
  tabulated.reserve(cells, static_cast<long long>(cells) * n, point_total, point_total * n);
  std::vector<int> basis(n);
  for (int cell = 0; cell < cells; ++cell) {
    for (int a = 0; a < n; ++a) basis[a] = mesh.cells(cell, a);
    const int material = rules.materials.empty() ? 0 : rules.materials[cell];
    if (!held[cell]) {
      const auto custom = rules.custom.find(cell);
      const QuadratureRule& rule = custom != rules.custom.end() ? custom->second : rules.standard;
      tabulated.add_held_elsewhere(basis, static_cast<int>(rule.weights.size()), material);
      continue;
    }
    const Eigen::MatrixXd& values = custom_values[cell].size() > 0 ? custom_values[cell] : standard.values;
    tabulated.add(basis, std::span<const double>(weights[cell].data(), weights[cell].size()), values, gradients[cell],
                  material);
  }
  return tabulated;
}

ElementTabulator lagrange_tabulator(const VolumeMesh& mesh, LagrangeCellRules rules,
                                    const NodeConstraints* constraints) {
  if (constraints && constraints->empty()) constraints = nullptr;
  return [&mesh, rules = std::move(rules), constraints](const TabulatedHere& here, const TabulatedElements*) {
    TabulatedElements elements = tabulate_lagrange(mesh, rules, here);
    // Not a conditional expression: its unconstrained branch would copy the elements.
    if (!constraints) return elements;
    return constrain_lagrange_elements(elements, *constraints);
  };
}

TabulatedElements tabulate_lagrange(const VolumeMesh& mesh, int quadrature_strength) {
  const bool tetrahedra = reference_element(mesh.element_type).shape() == ElementShape::tetrahedron;
  return tabulate_lagrange(
      mesh, LagrangeCellRules{tetrahedra ? tet_rule(quadrature_strength) : hex_rule(quadrature_strength), {}, {}});
}

}  // namespace altfem
