#include "shared/fem/lagrange_element_masses.hpp"

#include <Eigen/LU>
#include <array>
#include <atomic>
#include <optional>
#include <string>

#include "shared/common/error.hpp"
#include "shared/element/geometry_map.hpp"
#include "shared/element/reference_element.hpp"

namespace altfem {

ElementMasses lagrange_element_masses(const VolumeMesh& mesh, const LagrangeCellRules& rules) {
  const ReferenceElement& element = reference_element(mesh.element_type);
  const int n = element.node_count();
  const auto cells = static_cast<int>(mesh.cells.rows());
  ElementMasses masses;
  masses.matrices.assign(cells, Eigen::MatrixXd::Zero(n, n));
  masses.integrals.assign(cells, Eigen::VectorXd::Zero(n));
  masses.volumes.assign(cells, 0.0);
  std::atomic<int> failed_cell{-1};
  // The standard rule's products on the reference cell, once: an affine cell with that
  // rule (every grid cell the material fills) takes them times its determinant.
  Eigen::MatrixXd standard_products;
  Eigen::VectorXd standard_integrals;
  element.integrate_products(rules.standard.points, rules.standard.weights, standard_products, standard_integrals);
  const double standard_volume = rules.standard.weights.sum();
#pragma omp parallel
  {
    // Per-thread scratch. All of a cell's points at once: its rules run to thousands of
    // points, and products over all of them beat a small product per point.
    Eigen::MatrixXd nodes(n, 3);
    std::array<Eigen::MatrixXd, 3> gradients, jacobian_columns;  // #points × #nodes; #points × 3
    Eigen::VectorXd weights;
#pragma omp for schedule(dynamic, 4)
    for (int cell = 0; cell < cells; ++cell) {
      const auto custom = rules.custom.find(cell);
      const QuadratureRule& rule = custom != rules.custom.end() ? custom->second : rules.standard;
      for (int a = 0; a < n; ++a) nodes.row(a) = mesh.nodes.row(mesh.cells(cell, a));
      weights.resize(rule.weights.size());
      bool degenerate = false;
      if (const std::optional<Eigen::Matrix3d> jacobian = affine_jacobian(element, nodes)) {
        // An affine cell (every grid cell): one determinant for all its points.
        const double determinant = jacobian->determinant();
        degenerate = !(determinant > 0);
        if (!degenerate && &rule == &rules.standard) {
          masses.matrices[cell] = determinant * standard_products;
          masses.integrals[cell] = determinant * standard_integrals;
          masses.volumes[cell] = determinant * standard_volume;
          continue;
        }
        weights = rule.weights * determinant;
      } else {
        element.evaluate_gradients_at(rule.points, gradients);
        // Row q of jacobian_columns[j] is ∂x/∂ξ_j at point q.
        for (int j = 0; j < 3; ++j) jacobian_columns[j].noalias() = gradients[j] * nodes;
        for (Eigen::Index q = 0; q < rule.weights.size() && !degenerate; ++q) {
          Eigen::Matrix3d jacobian_at_point;
          for (int j = 0; j < 3; ++j) jacobian_at_point.col(j) = jacobian_columns[j].row(q).transpose();
          const double determinant = jacobian_at_point.determinant();
          degenerate = !(determinant > 0);
          weights[q] = rule.weights[q] * determinant;
        }
      }
      if (degenerate) {
        int expected = -1;
        failed_cell.compare_exchange_strong(expected, cell);
        continue;
      }
      masses.volumes[cell] = weights.sum();
      element.integrate_products(rule.points, weights, masses.matrices[cell], masses.integrals[cell]);
    }
  }
  if (failed_cell >= 0)
    throw NumericalError("cell " + std::to_string(failed_cell.load()) +
                         ": det J <= 0 at a mass quadrature point "
                         "(inverted or degenerate " +
                         std::string(element_name(mesh.element_type)) + ")");
  return masses;
}

}  // namespace altfem
