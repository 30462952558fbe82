#include "shared/fem/lagrange_element_masses.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <atomic>
#include <optional>
#include <string>
#include <vector>

#include "shared/common/error.hpp"
#include "shared/element/geometry_map.hpp"
#include "shared/element/reference_element.hpp"

namespace altfem {

namespace {

/// A large rule's points in this many chunks, whatever the thread count, summed in order:
/// the same masses on any machine.
constexpr int large_rule_chunks = 16;

/// integrate_products over all threads, in large_rule_chunks chunks summed in order.
void integrate_products_in_chunks(const ReferenceElement& element, const Eigen::MatrixXd& points,
                                  const Eigen::VectorXd& weights, Eigen::MatrixXd& products,
                                  Eigen::VectorXd& integrals) {
  const Eigen::Index count = weights.size();
  std::vector<Eigen::MatrixXd> chunk_products(large_rule_chunks);
  std::vector<Eigen::VectorXd> chunk_integrals(large_rule_chunks);
#pragma omp parallel for schedule(dynamic, 1)
  for (int chunk = 0; chunk < large_rule_chunks; ++chunk) {
    const Eigen::Index begin = count * chunk / large_rule_chunks, end = count * (chunk + 1) / large_rule_chunks;
    element.integrate_products(points.middleRows(begin, end - begin), weights.segment(begin, end - begin),
                               chunk_products[chunk], chunk_integrals[chunk]);
  }
  products = chunk_products[0];
  integrals = chunk_integrals[0];
  for (int chunk = 1; chunk < large_rule_chunks; ++chunk) {
    products += chunk_products[chunk];
    integrals += chunk_integrals[chunk];
  }
}

struct CellScratch {
  Eigen::MatrixXd nodes;
  std::array<Eigen::MatrixXd, 3> gradients, jacobian_columns;  // #points × #nodes; #points × 3
};

/// The weights of `rule` times |det J| at its points in `cell` (one determinant when the
/// cell is affine, every grid cell); false where a determinant is not positive.
bool physical_weights(const ReferenceElement& element, const VolumeMesh& mesh, int cell, const QuadratureRule& rule,
                      CellScratch& scratch, Eigen::VectorXd& weights, std::optional<double>& affine_determinant) {
  const int n = element.node_count();
  scratch.nodes.resize(n, 3);
  for (int a = 0; a < n; ++a) scratch.nodes.row(a) = mesh.nodes.row(mesh.cells(cell, a));
  affine_determinant.reset();
  if (const std::optional<Eigen::Matrix3d> jacobian = affine_jacobian(element, scratch.nodes)) {
    affine_determinant = jacobian->determinant();
    weights = rule.weights * *affine_determinant;
    return *affine_determinant > 0;
  }
  weights.resize(rule.weights.size());
  element.evaluate_gradients_at(rule.points, scratch.gradients);
  // Row q of jacobian_columns[j] is ∂x/∂ξ_j at point q.
  for (int j = 0; j < 3; ++j) scratch.jacobian_columns[j].noalias() = scratch.gradients[j] * scratch.nodes;
  for (Eigen::Index q = 0; q < rule.weights.size(); ++q) {
    Eigen::Matrix3d jacobian_at_point;
    for (int j = 0; j < 3; ++j) jacobian_at_point.col(j) = scratch.jacobian_columns[j].row(q).transpose();
    const double determinant = jacobian_at_point.determinant();
    if (!(determinant > 0)) return false;
    weights[q] = rule.weights[q] * determinant;
  }
  return true;
}

}  // namespace

ReferenceProducts reference_products(ElementType type, const QuadratureRule& rule) {
  ReferenceProducts reduced;
  const ReferenceElement& element = reference_element(type);
  if (rule.weights.size() > large_rule_points)
    integrate_products_in_chunks(element, rule.points, rule.weights, reduced.products, reduced.integrals);
  else element.integrate_products(rule.points, rule.weights, reduced.products, reduced.integrals);
  reduced.weight_sum = rule.weights.sum();
  return reduced;
}

ElementMasses lagrange_element_masses(const VolumeMesh& mesh, const LagrangeCellRules& rules,
                                      const std::unordered_map<int, ReferenceProducts>& reduced) {
  const ReferenceElement& element = reference_element(mesh.element_type);
  const int n = element.node_count();
  const auto cells = static_cast<int>(mesh.cells.rows());
  ElementMasses masses;
  masses.matrices.assign(cells, Eigen::MatrixXd::Zero(n, n));
  masses.integrals.assign(cells, Eigen::VectorXd::Zero(n));
  masses.volumes.assign(cells, 0.0);
  std::atomic<int> failed_cell{-1};
  const auto fail = [&](int cell) {
    int expected = -1;
    failed_cell.compare_exchange_strong(expected, cell);
  };
  const auto rule_of = [&](int cell) -> const QuadratureRule& {
    const auto custom = rules.custom.find(cell);
    return custom != rules.custom.end() ? custom->second : rules.standard;
  };
  // The standard rule's products on the reference cell, once: an affine cell with that
  // rule (every grid cell the material fills) takes them times its determinant.
  Eigen::MatrixXd standard_products;
  Eigen::VectorXd standard_integrals;
  element.integrate_products(rules.standard.points, rules.standard.weights, standard_products, standard_integrals);
  const double standard_volume = rules.standard.weights.sum();
  std::vector<int> large_cells;
#pragma omp parallel
  {
    // Per-thread scratch. All of a cell's points at once: its rules run to thousands of
    // points, and products over all of them beat a small product per point.
    CellScratch scratch;
    Eigen::VectorXd weights;
    std::optional<double> affine_determinant;
#pragma omp for schedule(dynamic, 4)
    for (int cell = 0; cell < cells; ++cell) {
      if (const auto found = reduced.find(cell); found != reduced.end()) {
        scratch.nodes.resize(n, 3);
        for (int a = 0; a < n; ++a) scratch.nodes.row(a) = mesh.nodes.row(mesh.cells(cell, a));
        if (const std::optional<Eigen::Matrix3d> jacobian = affine_jacobian(element, scratch.nodes)) {
          const double determinant = jacobian->determinant();
          if (!(determinant > 0)) {
            fail(cell);
            continue;
          }
          masses.matrices[cell] = determinant * found->second.products;
          masses.integrals[cell] = determinant * found->second.integrals;
          masses.volumes[cell] = determinant * found->second.weight_sum;
          continue;
        }
      }
      const QuadratureRule& rule = rule_of(cell);
      if (rule.weights.size() > large_rule_points) {
#pragma omp critical(altfem_large_mass_rules)
        large_cells.push_back(cell);
        continue;
      }
      if (!physical_weights(element, mesh, cell, rule, scratch, weights, affine_determinant)) {
        fail(cell);
        continue;
      }
      if (affine_determinant && &rule == &rules.standard) {
        masses.matrices[cell] = *affine_determinant * standard_products;
        masses.integrals[cell] = *affine_determinant * standard_integrals;
        masses.volumes[cell] = *affine_determinant * standard_volume;
        continue;
      }
      masses.volumes[cell] = weights.sum();
      element.integrate_products(rule.points, weights, masses.matrices[cell], masses.integrals[cell]);
    }
  }
  std::sort(large_cells.begin(), large_cells.end());
  CellScratch scratch;
  Eigen::VectorXd weights;
  std::optional<double> affine_determinant;
  for (const int cell : large_cells) {
    const QuadratureRule& rule = rule_of(cell);
    if (!physical_weights(element, mesh, cell, rule, scratch, weights, affine_determinant)) {
      fail(cell);
      continue;
    }
    masses.volumes[cell] = weights.sum();
    integrate_products_in_chunks(element, rule.points, weights, masses.matrices[cell], masses.integrals[cell]);
  }
  if (failed_cell >= 0)
    throw NumericalError("cell " + std::to_string(failed_cell.load()) +
                         ": det J <= 0 at a mass quadrature point "
                         "(inverted or degenerate " +
                         std::string(element_name(mesh.element_type)) + ")");
  return masses;
}

}  // namespace altfem
