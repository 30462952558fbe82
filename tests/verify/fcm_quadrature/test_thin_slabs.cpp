// Simplification where the moments are nearly dependent (Longva et al. 2020, §4.4): a
// rotated slab of thickness 1e-2 … 1e-8 through a Hex20 cell, whose intersection rule's
// points almost lie in a plane, so polynomials vanishing on that plane make P nearly
// rank-deficient. Every simplifier keeps the moments to rounding (residual <= 1e-14,
// where the accepted tolerance is 1e-12: a rank decision taken too early would show
// here as ≈ 1e-13), with at most M positive weights and the volume kept.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cstdio>

#include "shared/cut_cells/cut_cell_rule.hpp"
#include "shared/element/reference_element.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "shared/quadrature/simplify_quadrature.hpp"
#include "simplification_methods.hpp"

namespace altfem::fcm {
namespace {

/// The intersection rule (degree `order`) of the reference Hex20 cell with a 3 × 3 × 1
/// tetrahedralised slab {0.3 <= z <= 0.3 + thickness}, rotated so no face is axis-aligned.
QuadratureRule slab_rule(double thickness, int order) {
  const VolumeMesh slab =
      structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d(-1.5, -1.5, 0.3), Eigen::Vector3d(1.5, 1.5, 0.3 + thickness)),
                      Eigen::Vector3i(3, 3, 1), ElementType::tet4);
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.2, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  std::vector<TetrahedronCorners> tetrahedra(slab.cells.rows());
  for (Eigen::Index t = 0; t < slab.cells.rows(); ++t)
    for (int c = 0; c < 4; ++c)
      tetrahedra[t].row(c) = (rotation * slab.nodes.row(slab.cells(t, c)).transpose()).transpose();
  const CellGeometry cell(ElementType::hex20, reference_element(ElementType::hex20).nodes().topRows(8));
  return intersection_rule(cell, tetrahedra, order).rule;
}

class ThinSlabs : public ::testing::TestWithParam<SimplificationMethod> {};

TEST_P(ThinSlabs, SimplifiedRulesKeepNearlyDependentMomentsToRounding) {
  std::printf("%10s %2s %6s %6s %10s\n", "thickness", "m", "N", "final", "residual");
  for (const double thickness : {1e-2, 1e-4, 1e-6, 1e-8}) {
    for (int m = 2; m <= 6; ++m) {
      const QuadratureRule rule = slab_rule(thickness, m);
      const SimplificationResult result = simplify_quadrature(rule, {m, GetParam(), 1e-12});
      std::printf("%10.0e %2d %6lld %6lld %10.2e\n", thickness, m, static_cast<long long>(rule.points.rows()),
                  static_cast<long long>(result.rule.points.rows()), result.residual);
      SCOPED_TRACE("thickness " + std::to_string(thickness) + ", m = " + std::to_string(m));
      EXPECT_TRUE(result.simplified);
      EXPECT_LE(result.residual, 1e-14);
      EXPECT_LE(result.rule.points.rows(), (m + 1) * (m + 2) * (m + 3) / 6);
      EXPECT_GT(result.rule.weights.minCoeff(), 0.0);
      EXPECT_NEAR(result.rule.weights.sum(), rule.weights.sum(), 1e-13 * rule.weights.sum());
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Methods, ThinSlabs, testing::every_simplification_method(),
                         testing::simplification_method_test_name);

}  // namespace
}  // namespace altfem::fcm
