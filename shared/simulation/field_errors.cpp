#include "shared/simulation/field_errors.hpp"

#include <cmath>

namespace altfem {

namespace {

// ∂u_i/∂X_j of the expression at every point: #points rows of 9 (row-major 3 × 3).
Eigen::MatrixXd exact_gradients(const VectorExpression& exact, const Eigen::MatrixXd& points, double time) {
  const double diagonal = (points.colwise().maxCoeff() - points.colwise().minCoeff()).norm();
  const double h = 1e-3 * (diagonal > 0 ? diagonal : 1.0);
  Eigen::MatrixXd gradients(points.rows(), 9);
  for (int j = 0; j < 3; ++j) {
    const auto shifted = [&](double offset) {
      Eigen::MatrixXd moved = points;
      moved.col(j).array() += offset;
      return evaluate_at_points(exact, moved, time);
    };
    // (−u(x + 2h) + 8u(x + h) − 8u(x − h) + u(x − 2h)) / 12h
    const Eigen::MatrixXd derivative = (8 * (shifted(h) - shifted(-h)) - (shifted(2 * h) - shifted(-2 * h))) / (12 * h);
    for (int i = 0; i < 3; ++i) gradients.col(3 * i + j) = derivative.col(i);
  }
  return gradients;
}

}  // namespace

FieldErrors field_errors(const FieldQuadrature& quadrature, const VectorExpression& exact,
                         const Eigen::VectorXd& displacement, double time) {
  const Eigen::MatrixXd values = evaluate_at_points(exact, quadrature.points, time);
  const Eigen::MatrixXd gradients = exact_gradients(exact, quadrature.points, time);
  const TabulatedElements& elements = *quadrature.elements;
  double l2 = 0, h1 = 0, exact_l2 = 0, exact_h1 = 0;
  Eigen::Index row = 0;
  for (int e = 0; e < elements.size(); ++e) {
    const ElementView element = elements[e];
    for (int q = 0; q < element.point_count(); ++q, ++row) {
      Eigen::Vector3d value = Eigen::Vector3d::Zero();
      Eigen::Matrix3d gradient = Eigen::Matrix3d::Zero();  // ∂u_i/∂X_j
      const auto basis_gradients = element.gradients_at(q);
      for (int a = 0; a < element.basis_count(); ++a) {
        const Eigen::Vector3d coefficient = displacement.segment<3>(3 * static_cast<Eigen::Index>(element.basis[a]));
        value += element.values(q, a) * coefficient;
        gradient += coefficient * basis_gradients.row(a);
      }
      const Eigen::Vector3d exact_value = values.row(row).transpose();
      const Eigen::Matrix3d exact_gradient =
          Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(Eigen::RowVectorXd(gradients.row(row)).data());
      const double w = element.weights[q];
      l2 += w * (value - exact_value).squaredNorm();
      h1 += w * (gradient - exact_gradient).squaredNorm();
      exact_l2 += w * exact_value.squaredNorm();
      exact_h1 += w * exact_gradient.squaredNorm();
    }
  }
  double sums[] = {l2, h1, exact_l2, exact_h1};  // over a share: the ranks' parts
  elements.sum_over_ranks(sums);
  return {std::sqrt(sums[0]), std::sqrt(sums[1]), std::sqrt(sums[2]), std::sqrt(sums[3]), quadrature.strength};
}

nlohmann::json field_errors_json(const FieldErrors& errors) {
  nlohmann::json result = {{"l2", errors.l2},
                           {"h1_seminorm", errors.h1_seminorm},
                           {"exact_l2", errors.exact_l2},
                           {"exact_h1_seminorm", errors.exact_h1_seminorm},
                           {"quadrature_strength", errors.strength}};
  if (errors.exact_l2 > 0) result["relative_l2"] = errors.l2 / errors.exact_l2;
  if (errors.exact_h1_seminorm > 0) result["relative_h1_seminorm"] = errors.h1_seminorm / errors.exact_h1_seminorm;
  return result;
}

}  // namespace altfem
