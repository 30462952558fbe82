#include "shared/fem/lagrange_element_masses.hpp"

#include <Eigen/LU>
#include <atomic>
#include <string>

#include "shared/common/error.hpp"
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
#pragma omp parallel
  {
    // Per-thread scratch: no allocation inside the loop over points.
    Eigen::VectorXd values(n);
    Eigen::MatrixXd gradients(n, 3);
    Eigen::MatrixXd nodes(n, 3);
#pragma omp for schedule(dynamic, 4)
    for (int cell = 0; cell < cells; ++cell) {
      const auto custom = rules.custom.find(cell);
      const QuadratureRule& rule = custom != rules.custom.end() ? custom->second : rules.standard;
      for (int a = 0; a < n; ++a) nodes.row(a) = mesh.nodes.row(mesh.cells(cell, a));
      Eigen::MatrixXd& matrix = masses.matrices[cell];
      Eigen::VectorXd& integral = masses.integrals[cell];
      double volume = 0;
      for (Eigen::Index q = 0; q < rule.weights.size(); ++q) {
        const Eigen::Vector3d xi = rule.points.row(q).transpose();
        element.evaluate(xi, values);
        element.evaluate_gradients(xi, gradients);
        const Eigen::Matrix3d jacobian = nodes.transpose().lazyProduct(gradients);  // no GEMM for 3 × n × 3
        const double determinant = jacobian.determinant();
        if (!(determinant > 0)) {
          int expected = -1;
          failed_cell.compare_exchange_strong(expected, cell);
          break;
        }
        const double weight = rule.weights[q] * determinant;
        volume += weight;
        integral.noalias() += weight * values;
        matrix.selfadjointView<Eigen::Lower>().rankUpdate(values, weight);
      }
      matrix = matrix.selfadjointView<Eigen::Lower>();
      masses.volumes[cell] = volume;
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
