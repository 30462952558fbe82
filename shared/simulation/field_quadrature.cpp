#include "shared/simulation/field_quadrature.hpp"

#include <algorithm>
#include <exception>

namespace altfem {

Eigen::MatrixXd nodal_quadrature_points(const TabulatedElements& elements, const Eigen::MatrixXd& nodes) {
  Eigen::MatrixXd points(elements.point_count(), 3);
  Eigen::Index row = 0;
  Eigen::MatrixXd element_nodes;
  for (int e = 0; e < elements.size(); ++e) {
    const ElementView element = elements[e];
    element_nodes.resize(element.basis_count(), 3);
    for (int a = 0; a < element.basis_count(); ++a) element_nodes.row(a) = nodes.row(element.basis[a]);
    points.middleRows(row, element.point_count()) = element.values * element_nodes;
    row += element.point_count();
  }
  return points;
}

Eigen::MatrixXd evaluate_at_points(const VectorExpression& expression, const Eigen::MatrixXd& points, double time) {
  // Chunks large enough that borrowing a parser (a locked pool) costs nothing.
  constexpr Eigen::Index chunk = 2048;
  const Eigen::Index count = points.rows();
  Eigen::MatrixXd values(count, 3);
  std::exception_ptr failure;  // an exception must not leave the OpenMP region
#pragma omp parallel for schedule(dynamic, 1)
  for (Eigen::Index begin = 0; begin < count; begin += chunk) {
    const Eigen::Index size = std::min(chunk, count - begin);
    try {
      values.middleRows(begin, size) = expression.evaluate(points.middleRows(begin, size), time);
    } catch (...) {
#pragma omp critical(altfem_evaluate_at_points)
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
  return values;
}

}  // namespace altfem
