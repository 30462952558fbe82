// Whole-mesh rule generation (shared/cut_cells/cell_rules.hpp): cells entirely inside get the
// standard rule; over seeded random rigid motions of random convex pieces (tetrahedra),
// the simplified rules of all cells together integrate every polynomial of degree <= m
// over the piece exactly, with at most M positive weights per cell.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>
#include <random>

#include "shared/cut_cells/cell_rules.hpp"
#include "shared/element/geometry_map.hpp"
#include "shared/element/reference_element.hpp"
#include "shared/geometry/polyhedron_moments.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "shared/quadrature/reference_rules.hpp"

namespace altfem::fcm {
namespace {

TEST(CellRules, CellsEntirelyInsideGetTheStandardRule) {
  const Eigen::AlignedBox3d box(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  const VolumeMesh embedded = structured_grid(box, Eigen::Vector3i(3, 3, 3), ElementType::tet4);
  for (const ElementType type : {ElementType::hex20, ElementType::tet10}) {
    const VolumeMesh background = structured_grid(box, Eigen::Vector3i(2, 2, 2), type);
    const CellRules rules = compute_cell_rules(background, embedded, {4});
    const QuadratureRule standard =
        reference_rule(type == ElementType::hex20 ? ReferenceDomain::hexahedron : ReferenceDomain::tetrahedron, 4);
    EXPECT_EQ(rules.inside_cells, background.cells.rows());
    for (const CellRule& cell : rules.cells) {
      EXPECT_EQ(cell.kind, CellKind::inside);
      EXPECT_EQ(cell.rule.points, standard.points);
      EXPECT_EQ(cell.rule.weights, standard.weights);
    }
  }
}

/// Σ over cells and points of w |J| (x − c)^a (y − c)^b (z − c)^c / s^(a+b+c), in
/// monomial_index order up to `degree` (the centred, scaled moments of polyhedron_moments).
Eigen::VectorXd rule_moments(const VolumeMesh& background, const CellRules& rules, int degree,
                             const Eigen::Vector3d& centre, double scale) {
  const ElementType corner_type =
      element_shape(background.element_type) == ElementShape::tetrahedron ? ElementType::tet4 : ElementType::hex8;
  const ReferenceElement& element = reference_element(corner_type);
  Eigen::VectorXd sums = Eigen::VectorXd::Zero((degree + 1) * (degree + 2) * (degree + 3) / 6);
  for (Eigen::Index c = 0; c < background.cells.rows(); ++c) {
    Eigen::MatrixXd corners(element.node_count(), 3);
    for (int i = 0; i < element.node_count(); ++i) corners.row(i) = background.nodes.row(background.cells(c, i));
    const QuadratureRule& rule = rules.cells[c].rule;
    for (Eigen::Index q = 0; q < rule.points.rows(); ++q) {
      const Eigen::Vector3d xi = rule.points.row(q).transpose();
      const Eigen::Vector3d y = (map_to_physical(element, corners, xi) - centre) / scale;
      const double weight = rule.weights(q) * std::abs(map_jacobian(element, corners, xi).determinant());
      int index = 0;
      for (int total = 0; total <= degree; ++total)
        for (int transverse = 0; transverse <= total; ++transverse)
          for (int k = 0; k <= transverse; ++k)
            sums(index++) +=
                weight * std::pow(y.x(), total - transverse) * std::pow(y.y(), transverse - k) * std::pow(y.z(), k);
    }
  }
  return sums;
}

TEST(CellRules, RandomRigidMotionsOfRandomConvexPieces) {
  std::mt19937 generator(2020);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const Eigen::AlignedBox3d box(Eigen::Vector3d::Constant(-1.0), Eigen::Vector3d::Constant(1.0));
  const VolumeMesh hexahedra = structured_grid(box, Eigen::Vector3i(3, 3, 3), ElementType::hex20);
  const VolumeMesh tetrahedra = structured_grid(box, Eigen::Vector3i(2, 2, 2), ElementType::tet10);
  const int order = 3;
  const int basis_size = 20;
  for (int trial = 0; trial < 200; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    // A random tetrahedron of the ball of radius 0.9, moved rigidly (stays in the box).
    const Eigen::Matrix3d rotation =
        Eigen::AngleAxisd(3.1 * unit(generator), Eigen::Vector3d::Random().normalized()).toRotationMatrix();
    VolumeMesh piece{ElementType::tet4, Eigen::MatrixXd(4, 3), (Eigen::MatrixXi(1, 4) << 0, 1, 2, 3).finished()};
    for (int c = 0; c < 4; ++c) {
      Eigen::Vector3d x(unit(generator), unit(generator), unit(generator));
      piece.nodes.row(c) = (rotation * (0.9 * x / std::max(1.0, x.norm()))).transpose();
    }
    Polyhedron boundary{piece.nodes, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
    const Eigen::Vector3d e1 = piece.nodes.row(1) - piece.nodes.row(0), e2 = piece.nodes.row(2) - piece.nodes.row(0),
                          e3 = piece.nodes.row(3) - piece.nodes.row(0);
    if (e1.cross(e2).dot(e3) < 0) {
      boundary.faces = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
    }
    const double volume = std::abs(e1.cross(e2).dot(e3)) / 6.0;
    if (volume < 1e-3) continue;  // nearly flat pieces say nothing about the rule
    const Eigen::Vector3d centre = piece.nodes.colwise().mean().transpose();
    const double scale = 0.9;
    const Eigen::VectorXd exact = polyhedron_moments(boundary, order, centre, scale);

    const VolumeMesh& background = trial % 2 ? tetrahedra : hexahedra;
    const CellRules rules = compute_cell_rules(background, piece, {order});
    EXPECT_EQ(rules.failed_simplifications, 0);
    double clipped = 0.0;
    for (const CellRule& cell : rules.cells) {
      clipped += cell.clipped_volume;
      if (cell.kind != CellKind::cut) continue;
      EXPECT_LE(cell.rule.points.rows(), basis_size);
      EXPECT_GT(cell.rule.weights.minCoeff(), 0.0);
    }
    EXPECT_NEAR(clipped, volume, 1e-13 * volume);
    const Eigen::VectorXd computed = rule_moments(background, rules, order, centre, scale);
    // |y| <= 2 on the piece, so ∫|f| <= volume · 2^degree: the error scale.
    for (Eigen::Index i = 0; i < exact.size(); ++i)
      EXPECT_NEAR(computed(i), exact(i), 1e-12 * volume * 8.0) << "moment " << i;
  }
}

}  // namespace
}  // namespace altfem::fcm
