// Octree rules (Longva et al. 2020, §4.1) against exact integrals and against the
// intersection rule on the same shape: a box (polyhedral and analytic at once) and a
// sphere in a Hex20 reference cell. The octree converges, slowly (error ~ leaf size);
// the intersection rule is exact. Prints the table.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "embedded_shapes.hpp"
#include "fcm/octree_rule.hpp"
#include "shared/element/reference_element.hpp"
#include "shared/mesh/structured_grid.hpp"

namespace altfem::fcm {
namespace {

double volume_of(const QuadratureRule& rule) { return rule.weights.sum(); }  // identity map: |J| = 1

TEST(OctreeRule, ConvergesSlowlyWhereIntersectionRulesAreExact) {
  const ReferenceElement& element = reference_element(ElementType::hex20);
  const CellGeometry cell(ElementType::hex20, element.nodes().topRows(8));
  const Eigen::Vector3d low(-0.63, -0.37, -0.71), high(0.41, 0.77, 0.53);
  const auto box = make_box(low, high);
  const double box_volume = (high - low).prod();
  const Eigen::Vector3d centre(0.05, -0.1, 0.08);
  const double radius = 0.6;
  const auto sphere = make_sphere(centre, radius);
  const double sphere_volume = 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;

  const VolumeMesh box_tetrahedra =
      structured_grid(Eigen::AlignedBox3d(low, high), Eigen::Vector3i(2, 2, 2), ElementType::tet4);
  const IntersectionRule intersection = intersection_rule(cell, testing::corner_matrices(box_tetrahedra), 4);
  const double intersection_error = std::abs(volume_of(intersection.rule) - box_volume) / box_volume;
  std::printf("intersection rule, box: %lld points, relative volume error %.2e\n",
              static_cast<long long>(intersection.rule.points.rows()), intersection_error);
  EXPECT_LE(intersection_error, 1e-14);

  std::printf("%5s %9s %12s %9s %12s\n", "depth", "box pts", "box error", "sph pts", "sphere error");
  std::vector<double> box_errors, sphere_errors;
  for (int depth = 1; depth <= 6; ++depth) {
    const QuadratureRule box_rule = octree_rule(cell, *box, {depth, 4});
    const QuadratureRule sphere_rule = octree_rule(cell, *sphere, {depth, 4});
    box_errors.push_back(std::abs(volume_of(box_rule) - box_volume) / box_volume);
    sphere_errors.push_back(std::abs(volume_of(sphere_rule) - sphere_volume) / sphere_volume);
    std::printf("%5d %9lld %12.2e %9lld %12.2e\n", depth, static_cast<long long>(box_rule.points.rows()),
                box_errors.back(), static_cast<long long>(sphere_rule.points.rows()), sphere_errors.back());
    EXPECT_GT(box_rule.weights.minCoeff(), 0.0);
  }
  // Converges, but not monotonically: Gauss points of cut leaves are kept or dropped
  // whole, so the error is only bounded by O(leaf size). The worse of depths 5–6 is at
  // least 4× below the worse of depths 1–2 (first order would give 16×)...
  const auto converged = [](const std::vector<double>& errors) {
    return std::max(errors[4], errors[5]) < std::max(errors[0], errors[1]) / 4.0;
  };
  EXPECT_TRUE(converged(box_errors));
  EXPECT_TRUE(converged(sphere_errors));
  // ...but slowly: with 4 more levels it is still far from the intersection rule's accuracy.
  EXPECT_GT(box_errors[5], 1e3 * std::max(intersection_error, 1e-16));
  EXPECT_GT(sphere_errors[5], 1e-6);
}

TEST(OctreeRule, CellsInsideOrOutsideAreClassifiedWithoutSubdivision) {
  const ReferenceElement& element = reference_element(ElementType::hex8);
  const CellGeometry cell(ElementType::hex8, element.nodes().topRows(8));
  const auto inside = octree_rule(cell, *make_sphere(Eigen::Vector3d::Zero(), 2.0), {5, 3});
  EXPECT_EQ(inside.points.rows(), 8);  // one 2×2×2 Gauss rule on the whole cell
  EXPECT_NEAR(inside.weights.sum(), 8.0, 1e-14);
  EXPECT_EQ(octree_rule(cell, *make_sphere(Eigen::Vector3d::Constant(5.0), 1.0), {5, 3}).points.rows(), 0);
}

}  // namespace
}  // namespace altfem::fcm
