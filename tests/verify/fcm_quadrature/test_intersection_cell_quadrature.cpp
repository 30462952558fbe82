// The intersection source of cell rules against the exact box source (fcm/
// box_cell_quadrature.hpp) on an axis-aligned body in a Hex20 grid: the same volume
// fractions and the same integrals of every polynomial up to the strength, stiffness rules
// simplified to at most M points; the affine cells' mass rules are their reductions alone,
// with the box rules' volumes and integrals of the basis functions; Hex20's mass rules of
// strength 10 stop at the degree of its basis' products (8) on these cells, with the same
// masses.
#include <gtest/gtest.h>

#include <cmath>

#include "fcm/box_cell_quadrature.hpp"
#include "shared/cut_cells/cell_rules.hpp"
#include "shared/cut_cells/intersection_cell_quadrature.hpp"
#include "shared/fem/lagrange_element_masses.hpp"
#include "shared/mesh/structured_grid.hpp"

namespace altfem::fcm {
namespace {

TEST(IntersectionCellQuadrature, AgreesWithExactBoxRules) {
  const VolumeMesh grid = structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d(2, 1, 1)),
                                          Eigen::Vector3i(4, 2, 2), ElementType::hex20);
  const Eigen::AlignedBox3d body(Eigen::Vector3d(0.1, 0.2, 0.15), Eigen::Vector3d(1.7, 0.9, 0.5));
  const VolumeMesh embedded = structured_grid(body, Eigen::Vector3i(3, 2, 2), ElementType::tet4);
  const int strength = 4;
  const auto exact = box_cell_quadrature(grid, body)(strength, RulePurpose::stiffness);
  const auto stiffness = intersection_cell_quadrature(grid, embedded)(strength, RulePurpose::stiffness);
  const auto mass = intersection_cell_quadrature(grid, embedded)(strength, RulePurpose::mass);
  ASSERT_EQ(exact.size(), stiffness.size());
  for (std::size_t c = 0; c < exact.size(); ++c) {
    SCOPED_TRACE("cell " + std::to_string(c));
    EXPECT_NEAR(stiffness[c].volume_fraction, exact[c].volume_fraction, 1e-13);
    EXPECT_EQ(stiffness[c].rule.has_value(), exact[c].rule.has_value());
    if (!exact[c].rule) continue;
    EXPECT_LE(stiffness[c].rule->points.rows(), 35);
    // Hex20's basis functions are of degree 4, so the box rule integrates them exactly.
    EXPECT_EQ(mass[c].rule->points.rows(), 0);
    ASSERT_TRUE(mass[c].reduced.has_value());
    const ReferenceProducts box = reference_products(ElementType::hex20, *exact[c].rule);
    EXPECT_NEAR(mass[c].reduced->weight_sum, box.weight_sum, 1e-13 * 8.0);
    EXPECT_LE((mass[c].reduced->integrals - box.integrals).cwiseAbs().maxCoeff(), 1e-13 * 8.0);
    // Reference-coordinate monomials up to the strength: the cells are affine boxes.
    for (int a = 0; a <= strength; ++a)
      for (int b = 0; a + b <= strength; ++b)
        for (int d = 0; a + b + d <= strength; ++d) {
          const auto integrate = [&](const QuadratureRule& rule) {
            double sum = 0.0;
            for (Eigen::Index q = 0; q < rule.points.rows(); ++q)
              sum += rule.weights(q) * std::pow(rule.points(q, 0), a) * std::pow(rule.points(q, 1), b) *
                     std::pow(rule.points(q, 2), d);
            return sum;
          };
          const double reference = integrate(*exact[c].rule);
          EXPECT_NEAR(integrate(*stiffness[c].rule), reference, 1e-13 * 8.0);
        }
  }
}

TEST(IntersectionCellQuadrature, AffineCellsMassRulesStopAtTheDegreeOfTheProducts) {
  const VolumeMesh grid = structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d(2, 1, 1)),
                                          Eigen::Vector3i(4, 2, 2), ElementType::hex20);
  const Eigen::AlignedBox3d body(Eigen::Vector3d(0.1, 0.2, 0.15), Eigen::Vector3d(1.7, 0.9, 0.5));
  const VolumeMesh embedded = structured_grid(body, Eigen::Vector3i(3, 2, 2), ElementType::tet4);
  const auto mass = intersection_cell_quadrature(grid, embedded)(10, RulePurpose::mass);
  // The same pieces with the strength asked for: a rule exact beyond the products' degree.
  CellRuleOptions full;
  full.order = 10;
  full.simplify = false;
  full.fan = PieceFan::vertex;
  full.reduce = true;
  const CellRules strength_ten = compute_cell_rules(grid, embedded, full);
  CellRuleOptions stopped = full;
  stopped.exact_degree = 8;
  const CellRules strength_eight = compute_cell_rules(grid, embedded, stopped);
  int cut = 0;
  for (std::size_t c = 0; c < mass.size(); ++c) {
    if (!mass[c].rule || !mass[c].reduced) continue;
    SCOPED_TRACE("cell " + std::to_string(c));
    ++cut;
    const CellRule& reference = strength_ten.cells[c];
    ASSERT_TRUE(reference.reduced.has_value());
    EXPECT_EQ(mass[c].rule->points.rows(), 0);  // the reduction alone
    EXPECT_LT(strength_eight.cells[c].initial_points, reference.initial_points);
    EXPECT_EQ(strength_eight.cells[c].reduced->products, mass[c].reduced->products);
    const double scale = reference.reduced->weight_sum;
    EXPECT_NEAR(mass[c].reduced->weight_sum, reference.reduced->weight_sum, 1e-13 * scale);
    EXPECT_LE((mass[c].reduced->products - reference.reduced->products).cwiseAbs().maxCoeff(), 1e-13 * scale);
    EXPECT_LE((mass[c].reduced->integrals - reference.reduced->integrals).cwiseAbs().maxCoeff(), 1e-13 * scale);
  }
  EXPECT_EQ(cut, 8);  // the grid's lower layer: the body lies in it and cuts each of its cells
}

}  // namespace
}  // namespace altfem::fcm
