#include "shared/fem/tabulate_lagrange.hpp"

#include <Eigen/LU>
#include <atomic>
#include <string>
#include <vector>

#include "shared/common/error.hpp"
#include "shared/element/reference_element.hpp"
#include "shared/quadrature/reference_rules.hpp"

namespace altfem {

TabulatedElements tabulate_lagrange(const VolumeMesh& mesh, int quadrature_strength) {
  const ReferenceElement& element = reference_element(mesh.element_type);
  const QuadratureRule rule = element.shape() == ElementShape::tetrahedron ? tet_rule(quadrature_strength)
                                                                           : hex_rule(quadrature_strength);
  const int n = element.node_count();
  const int points = static_cast<int>(rule.weights.size());
  const int cells = static_cast<int>(mesh.cells.rows());

  // Reference values and gradients are the same for every cell: compute them once.
  Eigen::MatrixXd values(points, n);
  std::vector<Eigen::MatrixXd> reference_gradients(points, Eigen::MatrixXd(n, 3));
  for (int q = 0; q < points; ++q) {
    Eigen::VectorXd row(n);
    element.evaluate(rule.points.row(q).transpose(), row);
    values.row(q) = row.transpose();
    element.evaluate_gradients(rule.points.row(q).transpose(), reference_gradients[q]);
  }

  // Physical data per cell, computed in parallel, then appended in cell order.
  std::vector<Eigen::VectorXd> weights(cells);
  std::vector<Eigen::MatrixXd> gradients(cells);
  std::atomic<int> failed_cell{-1};
  std::atomic<int> failed_point{-1};
#pragma omp parallel for schedule(static)
  for (int cell = 0; cell < cells; ++cell) {
    Eigen::MatrixXd nodes(n, 3);
    for (int a = 0; a < n; ++a) nodes.row(a) = mesh.nodes.row(mesh.cells(cell, a));
    weights[cell].resize(points);
    gradients[cell].resize(static_cast<Eigen::Index>(points) * n, 3);
    for (int q = 0; q < points; ++q) {
      const Eigen::Matrix3d jacobian = nodes.transpose() * reference_gradients[q];  // ∂x_i/∂ξ_j
      const double determinant = jacobian.determinant();
      if (!(determinant > 0)) {
        int expected = -1;
        if (failed_cell.compare_exchange_strong(expected, cell)) failed_point = q;
        break;
      }
      weights[cell][q] = rule.weights[q] * determinant;
      gradients[cell].middleRows(static_cast<Eigen::Index>(q) * n, n) = reference_gradients[q] * jacobian.inverse();
    }
  }
  if (failed_cell >= 0)
    throw NumericalError("cell " + std::to_string(failed_cell.load()) + ": det J <= 0 at quadrature point " +
                         std::to_string(failed_point.load()) + " (inverted or degenerate " +
                         std::string(element_name(mesh.element_type)) + ")");

  TabulatedElements tabulated;
  tabulated.reserve(cells, static_cast<long long>(cells) * n, static_cast<long long>(cells) * points,
                    static_cast<long long>(cells) * points * n);
  std::vector<int> basis(n);
  for (int cell = 0; cell < cells; ++cell) {
    for (int a = 0; a < n; ++a) basis[a] = mesh.cells(cell, a);
    tabulated.add(basis, std::span<const double>(weights[cell].data(), points), values, gradients[cell]);
  }
  return tabulated;
}

}  // namespace altfem
