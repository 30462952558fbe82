#include "shared/fem/tabulate_lagrange.hpp"

#include <Eigen/LU>
#include <array>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <functional>
#include <map>
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

// Per cell, the first cell before it whose tabulation is bit for bit its own, else −1:
// both held, on the standard rule without hanging nodes (`plain`), affine with the same
// Jacobian to the last bit, so that their weights, values and gradients are the same
// numbers. A grid's cells of one size are few such classes; tabulated once each, they
// share it (TabulatedElements' same_points_as), where the tabulation was most of the
// memory a grid's discretization holds.
std::vector<int> equal_cells(const VolumeMesh& mesh, const ReferenceElement& element, const std::vector<char>& held,
                             const std::function<bool(int)>& plain) {
  const int cells = static_cast<int>(mesh.cells.rows()), n = element.node_count();
  std::vector<std::optional<Eigen::Matrix3d>> jacobians(cells);
#pragma omp parallel
  {
    Eigen::MatrixXd nodes(n, 3);
#pragma omp for schedule(dynamic, 64)
    for (int cell = 0; cell < cells; ++cell) {
      if (!held[cell] || !plain(cell)) continue;
      for (int a = 0; a < n; ++a) nodes.row(a) = mesh.nodes.row(mesh.cells(cell, a));
      jacobians[cell] = affine_jacobian(element, nodes);
    }
  }
  std::vector<int> same_as(cells, -1);
  std::map<std::array<std::uint64_t, 9>, int> first;  // a Jacobian's bits → its first cell
  for (int cell = 0; cell < cells; ++cell) {
    if (!jacobians[cell]) continue;
    std::array<std::uint64_t, 9> bits{};
    std::memcpy(bits.data(), jacobians[cell]->data(), sizeof bits);
    const auto [entry, inserted] = first.try_emplace(bits, cell);
    if (!inserted) same_as[cell] = entry->second;
  }
  return same_as;
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

  // The cells' bases first (a cell with hanging nodes hands their functions to their masters,
  // substitute_hanging), so that the tabulation is laid out at its full size; then every cell
  // writes its weights, values and gradients straight into its place, in parallel (a
  // tabulation appended cell by cell was a serial copy of all of it, into zeroed memory).
  std::vector<std::vector<int>> constrained_basis(constraints ? cells : 0);
  std::vector<Eigen::MatrixXd> substitutions(constraints ? cells : 0);  // #nodes × #basis, hanging cells only
  if (constraints) {
#pragma omp parallel
    {
      std::vector<int> nodes(n);
#pragma omp for schedule(dynamic, 64)
      for (int cell = 0; cell < cells; ++cell) {
        for (int a = 0; a < n; ++a) nodes[a] = mesh.cells(cell, a);
        if (any_hanging(nodes, *constraints))
          substitute_hanging(nodes, *constraints, constrained_basis[cell], substitutions[cell]);
      }
    }
  }
  const std::vector<char> held = tabulated_here(here, cells);
  const std::vector<int> same_as = equal_cells(mesh, element, held, [&](int cell) {
    return &rule_of(cell) == &rules.standard && !(constraints && !constrained_basis[cell].empty());
  });
  TabulatedElements tabulated;
  {
    std::vector<int> nodes(n);
    tabulated.lay_out(cells, [&](int cell) {
      std::span<const int> basis = nodes;
      if (constraints && !constrained_basis[cell].empty()) {
        basis = constrained_basis[cell];
      } else {
        for (int a = 0; a < n; ++a) nodes[a] = mesh.cells(cell, a);
      }
      return ElementLayout{basis, static_cast<int>(rule_of(cell).weights.size()),
                           rules.materials.empty() ? 0 : rules.materials[cell], held[cell] != 0, same_as[cell]};
    });
  }

  std::atomic<int> failed_cell{-1};
  std::atomic<int> failed_point{-1};
#pragma omp parallel
  {
    Eigen::MatrixXd cell_nodes(n, 3), reference_gradients(n, 3);  // per thread
    Eigen::VectorXd gradient_storage;                             // per thread, grown to the largest cell
#pragma omp for schedule(dynamic, 16)
    for (int cell = 0; cell < cells; ++cell) {
      if (!held[cell] || same_as[cell] >= 0) continue;
      const QuadratureRule& rule = rule_of(cell);
      const bool own_rule = &rule != &rules.standard;
      ReferenceTable own;
      if (own_rule) own = reference_table(element, rule);
      const ReferenceTable& table = own_rule ? own : standard;
      const auto points = static_cast<int>(rule.weights.size());
      ElementSlots slots = tabulated.slots(cell);
      Eigen::Map<Eigen::VectorXd> weights(slots.weights.data(), points);
      for (int a = 0; a < n; ++a) cell_nodes.row(a) = mesh.nodes.row(mesh.cells(cell, a));
      if (gradient_storage.size() < 3 * static_cast<Eigen::Index>(points) * n)
        gradient_storage.resize(3 * static_cast<Eigen::Index>(points) * n);
      Eigen::Map<Eigen::MatrixXd> gradients(gradient_storage.data(), static_cast<Eigen::Index>(points) * n, 3);
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
        weights = rule.weights * determinant;
        const Eigen::Matrix3d inverse = jacobian->inverse();
        for (int k = 0; k < 3; ++k)
          Eigen::Map<Eigen::MatrixXd>(gradients.col(k).data(), n, points) =
              inverse(0, k) * table.gradients[0].transpose() + inverse(1, k) * table.gradients[1].transpose() +
              inverse(2, k) * table.gradients[2].transpose();
      } else {
        // Coefficient-wise products: these are 3 × #nodes × 3 at every point, which Eigen
        // would otherwise hand to its blocked matrix product, packing both operands each time.
        bool inverted = false;
        for (int q = 0; q < points && !inverted; ++q) {
          for (int j = 0; j < 3; ++j) reference_gradients.col(j) = table.gradients[j].row(q).transpose();
          const Eigen::Matrix3d point_jacobian = cell_nodes.transpose().lazyProduct(reference_gradients);  // ∂x_i/∂ξ_j
          const double determinant = point_jacobian.determinant();
          if (!(determinant > 0)) {
            int expected = -1;
            if (failed_cell.compare_exchange_strong(expected, cell)) failed_point = q;
            inverted = true;
            break;
          }
          weights[q] = rule.weights[q] * determinant;
          gradients.middleRows(static_cast<Eigen::Index>(q) * n, n) =
              reference_gradients.lazyProduct(point_jacobian.inverse());
        }
        if (inverted) continue;
      }
      if (!constraints || constrained_basis[cell].empty()) {
        slots.values = table.values;
        slots.gradients = gradients;
        continue;
      }
      // N' = N S: values and each point's gradients (#basis × 3) = Sᵀ (#nodes × 3).
      const Eigen::MatrixXd& substitution = substitutions[cell];
      const auto basis_size = substitution.cols();
      slots.values = table.values * substitution;
      for (int q = 0; q < points; ++q)
        slots.gradients.middleRows(q * basis_size, basis_size) =
            substitution.transpose() * gradients.middleRows(static_cast<Eigen::Index>(q) * n, n);
    }
  }
  if (failed_cell >= 0)
    throw NumericalError("cell " + std::to_string(failed_cell.load()) + ": det J <= 0 at quadrature point " +
                         std::to_string(failed_point.load()) + " (inverted or degenerate " +
                         std::string(element_name(mesh.element_type)) + ")");
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
