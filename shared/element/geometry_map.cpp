#include "shared/element/geometry_map.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <stdexcept>
#include <string>

namespace altfem {

namespace {
using NodeValues = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, ReferenceElement::max_node_count, 1>;
using NodeGradients = Eigen::Matrix<double, Eigen::Dynamic, 3, 0, ReferenceElement::max_node_count, 3>;

constexpr int max_step_halvings = 30;
// ξ may sit this far outside the reference domain and still count as inside, so
// points on a shared face are found in both elements despite round-off.
constexpr double minimum_inside_slack = 1e-10;

void check_shape(const ReferenceElement& element, const Eigen::Ref<const Eigen::MatrixXd>& nodes) {
  if (nodes.rows() != element.node_count() || nodes.cols() != 3)
    throw std::invalid_argument("geometry map of " + std::string(element_name(element.type())) +
                                ": element_nodes must be " + std::to_string(element.node_count()) + " × 3, got " +
                                std::to_string(nodes.rows()) + " × " + std::to_string(nodes.cols()));
}

Eigen::Vector3d physical_point(const ReferenceElement& element, const Eigen::Ref<const Eigen::MatrixXd>& nodes,
                               const Eigen::Vector3d& xi) {
  NodeValues values(element.node_count());
  element.evaluate(xi, values);
  return nodes.transpose().lazyProduct(values);
}

Eigen::Matrix3d jacobian(const ReferenceElement& element, const Eigen::Ref<const Eigen::MatrixXd>& nodes,
                         const Eigen::Vector3d& xi) {
  NodeGradients gradients(element.node_count(), 3);
  element.evaluate_gradients(xi, gradients);
  return nodes.transpose().lazyProduct(gradients);
}
}  // namespace

Eigen::Vector3d map_to_physical(const ReferenceElement& element, const Eigen::Ref<const Eigen::MatrixXd>& element_nodes,
                                const Eigen::Vector3d& xi) {
  check_shape(element, element_nodes);
  return physical_point(element, element_nodes, xi);
}

Eigen::Matrix3d map_jacobian(const ReferenceElement& element, const Eigen::Ref<const Eigen::MatrixXd>& element_nodes,
                             const Eigen::Vector3d& xi) {
  check_shape(element, element_nodes);
  return jacobian(element, element_nodes, xi);
}

std::optional<Eigen::Matrix3d> affine_jacobian(const ReferenceElement& element,
                                               const Eigen::Ref<const Eigen::MatrixXd>& element_nodes) {
  check_shape(element, element_nodes);
  const Eigen::Vector3d centre = element.centroid();
  const Eigen::Matrix3d jacobian_at_centre = jacobian(element, element_nodes, centre);
  const Eigen::Vector3d image_of_centre = physical_point(element, element_nodes, centre);
  const Eigen::Vector3d extent = element_nodes.colwise().maxCoeff() - element_nodes.colwise().minCoeff();
  const double tolerance = 1e-12 * extent.norm();
  for (int a = 0; a < element.node_count(); ++a) {
    const Eigen::Vector3d affine = image_of_centre + jacobian_at_centre * (element.nodes().row(a).transpose() - centre);
    if ((element_nodes.row(a).transpose() - affine).norm() > tolerance) return std::nullopt;
  }
  return jacobian_at_centre;
}

InverseMapResult map_to_reference(const ReferenceElement& element,
                                  const Eigen::Ref<const Eigen::MatrixXd>& element_nodes, const Eigen::Vector3d& x,
                                  double tolerance, int max_iterations) {
  check_shape(element, element_nodes);
  const double diameter = (element_nodes.colwise().maxCoeff() - element_nodes.colwise().minCoeff()).norm();
  // A Jacobian this close to singular (relative to the element's size) has no
  // meaningful Newton step.
  const double singular_determinant = 1e-14 * diameter * diameter * diameter;

  InverseMapResult result{element.centroid(), false, false, 0, 0.0};
  Eigen::Vector3d residual = physical_point(element, element_nodes, result.xi) - x;
  while (true) {
    Eigen::Matrix3d inverse;
    double determinant = 0.0;
    bool invertible = false;
    jacobian(element, element_nodes, result.xi)
        .computeInverseAndDetWithCheck(inverse, determinant, invertible, singular_determinant);
    if (!invertible) break;
    const Eigen::Vector3d step = -inverse * residual;
    if (step.lpNorm<Eigen::Infinity>() <= tolerance) {
      // Near the root Newton converges quadratically, so taking this last small
      // step leaves ξ far more accurate than `tolerance`, for one map evaluation.
      result.xi += step;
      residual = physical_point(element, element_nodes, result.xi) - x;
      result.converged = true;
      break;
    }
    if (result.iterations >= max_iterations) break;

    const double residual_norm = residual.norm();
    double fraction = 1.0;
    Eigen::Vector3d trial = result.xi + step;
    Eigen::Vector3d trial_residual = physical_point(element, element_nodes, trial) - x;
    for (int halvings = 0; trial_residual.norm() >= residual_norm && halvings < max_step_halvings; ++halvings) {
      fraction *= 0.5;
      trial = result.xi + fraction * step;
      trial_residual = physical_point(element, element_nodes, trial) - x;
    }
    if (trial_residual.norm() >= residual_norm) break;
    ++result.iterations;
    result.xi = trial;
    residual = trial_residual;
  }
  result.residual = residual.norm();
  result.inside = result.converged && element.contains(result.xi, std::max(tolerance, minimum_inside_slack));
  return result;
}

}  // namespace altfem
