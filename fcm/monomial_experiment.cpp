#include "fcm/monomial_experiment.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "shared/cut_cells/cut_cell_rule.hpp"
#include "shared/element/reference_element.hpp"
#include "shared/mesh/structured_grid.hpp"

namespace altfem::fcm {
namespace {

/// The cuboid: [lower, upper] in its own frame y; world x = rotation · y + translation.
struct Cuboid {
  Eigen::Vector3d lower, upper;
  Eigen::Matrix3d rotation;
  Eigen::Vector3d translation;
};

/// A cuboid well inside the reference cell: the rotation is about a skew axis, so no
/// cuboid face is parallel to a cell face. The local frame is shifted off the origin
/// so that odd monomials do not integrate to zero.
Cuboid cuboid_in(ElementShape shape) {
  Cuboid cuboid;
  cuboid.rotation = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
  const Eigen::Vector3d half =
      shape == ElementShape::hexahedron ? Eigen::Vector3d(0.55, 0.4, 0.3) : Eigen::Vector3d(0.09, 0.07, 0.05);
  const Eigen::Vector3d centre =
      shape == ElementShape::hexahedron ? Eigen::Vector3d(0.1, -0.05, 0.08) : Eigen::Vector3d(0.25, 0.24, 0.23);
  cuboid.lower = half;  // local box [half, 3·half]: centred at 2·half in its frame
  cuboid.upper = 3.0 * half;
  cuboid.translation = centre - cuboid.rotation * (2.0 * half);
  return cuboid;
}

/// Measures `rule` (reference = world coordinates) against the exact monomial integrals.
RuleAccuracy measure(const QuadratureRule& rule, const Cuboid& cuboid, int order) {
  RuleAccuracy accuracy;
  accuracy.points = rule.points.rows();
  accuracy.min_weight = rule.weights.size() ? rule.weights.minCoeff() : 0.0;
  const Eigen::MatrixXd local =
      (rule.points.rowwise() - cuboid.translation.transpose()) * cuboid.rotation;  // rows: Rᵀ(x − t)
  const double slack = 1e-12;
  for (Eigen::Index q = 0; q < local.rows(); ++q) {
    const Eigen::Vector3d y = local.row(q).transpose();
    accuracy.inside &= ((y - cuboid.lower).array() >= -slack).all() && ((cuboid.upper - y).array() >= -slack).all();
  }
  std::vector<double> errors;
  for (int a = 0; a <= order; ++a)
    for (int b = 0; a + b <= order; ++b)
      for (int c = 0; a + b + c <= order; ++c) {
        const Eigen::Vector3i exponent(a, b, c);
        double exact = 1.0;
        for (int d = 0; d < 3; ++d) {
          const int e = exponent(d);
          exact *= (std::pow(cuboid.upper(d), e + 1) - std::pow(cuboid.lower(d), e + 1)) / (e + 1);
        }
        double sum = 0.0;
        for (Eigen::Index q = 0; q < local.rows(); ++q) {
          sum += rule.weights(q) * std::pow(local(q, 0), a) * std::pow(local(q, 1), b) * std::pow(local(q, 2), c);
        }
        // The integrand is positive on the cuboid: max(|exact|, ∫|f|) = exact.
        errors.push_back(std::abs(sum - exact) / exact);
      }
  std::sort(errors.begin(), errors.end());
  accuracy.max_relative_error = errors.back();
  accuracy.median_relative_error = errors[errors.size() / 2];
  return accuracy;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

MonomialExperiment run_monomial_experiment(ElementType cell, int order, SimplificationMethod method) {
  MonomialExperiment experiment;
  experiment.cell = cell;
  experiment.order = order;
  experiment.basis_size = (order + 1) * (order + 2) * (order + 3) / 6;
  const ElementShape shape = element_shape(cell);
  const Cuboid cuboid = cuboid_in(shape);

  // The cuboid as six tetrahedra (Kuhn), moved rigidly into place.
  const VolumeMesh box =
      structured_grid(Eigen::AlignedBox3d(cuboid.lower, cuboid.upper), Eigen::Vector3i::Ones(), ElementType::tet4);
  std::vector<TetrahedronCorners> tetrahedra(box.cells.rows());
  for (Eigen::Index t = 0; t < box.cells.rows(); ++t) {
    for (int c = 0; c < 4; ++c) {
      const Eigen::Vector3d y = box.nodes.row(box.cells(t, c)).transpose();
      tetrahedra[t].row(c) = (cuboid.rotation * y + cuboid.translation).transpose();
    }
  }
  const ReferenceElement& element = reference_element(cell);
  const CellGeometry geometry(cell, element.nodes().topRows(element_corner_count(cell)));

  const auto start = std::chrono::steady_clock::now();
  const IntersectionRule intersection = intersection_rule(geometry, tetrahedra, order);
  experiment.generation_seconds = seconds_since(start);
  const auto middle = std::chrono::steady_clock::now();
  const SimplificationResult simplified = simplify_quadrature(intersection.rule, {order, method, 1e-12});
  experiment.simplification_seconds = seconds_since(middle);

  experiment.initial = measure(intersection.rule, cuboid, order);
  experiment.simplified = measure(simplified.rule, cuboid, order);
  experiment.residual = simplified.residual;
  experiment.simplification_failed = simplified.failed;
  return experiment;
}

}  // namespace altfem::fcm
