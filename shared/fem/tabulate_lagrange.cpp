#include "shared/fem/tabulate_lagrange.hpp"

#include <Eigen/LU>
#include <array>
#include <atomic>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "shared/assembly/tabulated_here.hpp"
#include "shared/common/error.hpp"
#include "shared/element/geometry_map.hpp"
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

TabulatedElements tabulate_lagrange(const VolumeMesh& mesh, const LagrangeCellRules& rules, const TabulatedHere& here,
                                    const NodeConstraints* constraints) {
  const ReferenceElement& element = reference_element(mesh.element_type);
  const int n = element.node_count();
  const int cells = static_cast<int>(mesh.cells.rows());
  if (constraints && constraints->empty()) constraints = nullptr;
  // The standard rule's reference table serves every cell that has no rule of its own.
  const ReferenceTable standard = reference_table(element, rules.standard);
  const auto rule_of = [&](int cell) -> const QuadratureRule& {
    const auto custom = rules.custom.find(cell);
    return custom != rules.custom.end() ? custom->second : rules.standard;
  };

  // Physical data per cell, computed in parallel, then appended in cell order. A cell with
  // hanging nodes gets its constrained basis here too, in the same pass: substituting them
  // in a second pass over the tabulation was a serial copy of all of it.
  std::vector<Eigen::VectorXd> weights(cells);
  std::vector<Eigen::MatrixXd> gradients(cells);
  std::vector<Eigen::MatrixXd> custom_values(cells);
  std::vector<std::vector<int>> constrained_basis(constraints ? cells : 0);
  std::atomic<int> failed_cell{-1};
  std::atomic<int> failed_point{-1};
  const std::vector<char> held = tabulated_here(here, cells);
#pragma omp parallel
  {
    Eigen::MatrixXd substitution, unconstrained, cell_nodes(n, 3), reference_gradients(n, 3);  // per thread
    std::vector<int> nodes(n);
#pragma omp for schedule(dynamic, 16)
    for (int cell = 0; cell < cells; ++cell) {
      for (int a = 0; a < n; ++a) nodes[a] = mesh.cells(cell, a);
      const bool hangs = constraints && any_hanging(nodes, *constraints);
      if (hangs) substitute_hanging(nodes, *constraints, constrained_basis[cell], substitution);
      if (!held[cell]) continue;
      const QuadratureRule& rule = rule_of(cell);
      const bool own_rule = &rule != &rules.standard;
      ReferenceTable own;
      if (own_rule) {
        own = reference_table(element, rule);
        custom_values[cell] = own.values;
      }
      const ReferenceTable& table = own_rule ? own : standard;
      const auto points = static_cast<int>(rule.weights.size());
      for (int a = 0; a < n; ++a) cell_nodes.row(a) = mesh.nodes.row(mesh.cells(cell, a));
      weights[cell].resize(points);
      gradients[cell].resize(static_cast<Eigen::Index>(points) * n, 3);
      // An affine cell (every grid cell) has one Jacobian: ∇N = (∂N/∂ξ) J⁻¹ at all its
      // points at once, column k of the gradients, seen as #nodes × #points, being
      // Σ_j J⁻¹(j, k) (∂N/∂ξ_j)ᵀ.
      if (const std::optional<Eigen::Matrix3d> jacobian = affine_jacobian(element, cell_nodes)) {
        const double determinant = jacobian->determinant();
        if (!(determinant > 0)) {
          int expected = -1;
          if (failed_cell.compare_exchange_strong(expected, cell)) failed_point = 0;
          continue;
        }
        weights[cell] = rule.weights * determinant;
        const Eigen::Matrix3d inverse = jacobian->inverse();
        for (int k = 0; k < 3; ++k)
          Eigen::Map<Eigen::MatrixXd>(gradients[cell].col(k).data(), n, points) =
              inverse(0, k) * table.gradients[0].transpose() + inverse(1, k) * table.gradients[1].transpose() +
              inverse(2, k) * table.gradients[2].transpose();
      } else {
        // Coefficient-wise products: these are 3 × #nodes × 3 at every point, which Eigen
        // would otherwise hand to its blocked matrix product, packing both operands each time.
        for (int q = 0; q < points; ++q) {
          for (int j = 0; j < 3; ++j) reference_gradients.col(j) = table.gradients[j].row(q).transpose();
          const Eigen::Matrix3d point_jacobian = cell_nodes.transpose().lazyProduct(reference_gradients);  // ∂x_i/∂ξ_j
          const double determinant = point_jacobian.determinant();
          if (!(determinant > 0)) {
            int expected = -1;
            if (failed_cell.compare_exchange_strong(expected, cell)) failed_point = q;
            break;
          }
          weights[cell][q] = rule.weights[q] * determinant;
          gradients[cell].middleRows(static_cast<Eigen::Index>(q) * n, n) =
              reference_gradients.lazyProduct(point_jacobian.inverse());
        }
      }
      if (!hangs) continue;
      // N' = N S: values and each point's gradients (#basis × 3) = Sᵀ (#nodes × 3).
      custom_values[cell] = table.values * substitution;
      unconstrained.swap(gradients[cell]);
      const auto basis_size = substitution.cols();
      gradients[cell].resize(static_cast<Eigen::Index>(points) * basis_size, 3);
      for (int q = 0; q < points; ++q)
        gradients[cell].middleRows(q * basis_size, basis_size) =
            substitution.transpose() * unconstrained.middleRows(static_cast<Eigen::Index>(q) * n, n);
    }
  }
  if (failed_cell >= 0)
    throw NumericalError("cell " + std::to_string(failed_cell.load()) + ": det J <= 0 at quadrature point " +
                         std::to_string(failed_point.load()) + " (inverted or degenerate " +
                         std::string(element_name(mesh.element_type)) + ")");

  std::vector<int> nodes(n);
  const auto basis_of = [&](int cell) -> std::span<const int> {
    if (constraints && !constrained_basis[cell].empty()) return constrained_basis[cell];
    for (int a = 0; a < n; ++a) nodes[a] = mesh.cells(cell, a);
    return nodes;
  };
  long long point_total = 0, basis_total = 0, value_total = 0;
  for (int cell = 0; cell < cells; ++cell) {
    const auto basis_size = static_cast<long long>(basis_of(cell).size());
    basis_total += basis_size;
    point_total += weights[cell].size();
    value_total += weights[cell].size() * basis_size;
  }
  TabulatedElements tabulated;
  tabulated.reserve(cells, basis_total, point_total, value_total);
  for (int cell = 0; cell < cells; ++cell) {
    const int material = rules.materials.empty() ? 0 : rules.materials[cell];
    if (!held[cell]) {
      tabulated.add_held_elsewhere(basis_of(cell), static_cast<int>(rule_of(cell).weights.size()), material);
      continue;
    }
    const Eigen::MatrixXd& values = custom_values[cell].size() > 0 ? custom_values[cell] : standard.values;
    tabulated.add(basis_of(cell), std::span<const double>(weights[cell].data(), weights[cell].size()), values,
                  gradients[cell], material);
  }
  return tabulated;
}

ElementTabulator lagrange_tabulator(const VolumeMesh& mesh, LagrangeCellRules rules,
                                    const NodeConstraints* constraints) {
  return [&mesh, rules = std::move(rules), constraints](const TabulatedHere& here, const TabulatedElements*) {
    return tabulate_lagrange(mesh, rules, here, constraints);
  };
}

TabulatedElements tabulate_lagrange(const VolumeMesh& mesh, int quadrature_strength,
                                    const NodeConstraints* constraints) {
  const bool tetrahedra = reference_element(mesh.element_type).shape() == ElementShape::tetrahedron;
  return tabulate_lagrange(
      mesh, LagrangeCellRules{tetrahedra ? tet_rule(quadrature_strength) : hex_rule(quadrature_strength), {}, {}},
      nullptr, constraints);
}

}  // namespace altfem
