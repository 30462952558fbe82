// Intersection rules (Longva et al. 2020, §4.5) against exact polyhedron moments: a
// tetrahedron, a box and a non-convex L-prism in every background cell type, with faces
// coincident with cell faces and vertices on cell edges, plus their mirror images just
// outside the cell (touching it with a face). Volume and first moments to 1e-13; the
// simplified rule keeps the volume to 1e-13; the vertex's fan (mass rules) integrates every
// monomial of the rule's degree as the centroid's does, from no more points.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "embedded_shapes.hpp"
#include "shared/cut_cells/cut_cell_rule.hpp"
#include "shared/element/reference_element.hpp"
#include "shared/geometry/polyhedron_moments.hpp"
#include "shared/quadrature/simplify_quadrature.hpp"

namespace altfem::fcm {
namespace {

using testing::EmbeddedShape;

struct CellCase {
  ElementType type;
  bool affine_map;  ///< false: the reference cell itself (exact coincidences)
};

class IntersectionMoments : public ::testing::TestWithParam<CellCase> {};

TEST_P(IntersectionMoments, VolumeAndFirstMomentsOfEmbeddedPolyhedra) {
  const auto [type, affine_map] = GetParam();
  const bool hexahedron = element_shape(type) == ElementShape::hexahedron;
  const ReferenceElement& element = reference_element(type);
  const Eigen::MatrixXd reference_corners = element.nodes().topRows(element_corner_count(type));
  // The physical cell: the reference cell under x = A ξ + b (or the identity).
  Eigen::Matrix3d A = Eigen::Matrix3d::Identity();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  if (affine_map) {
    A = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, -1, 2).normalized()).toRotationMatrix() *
        Eigen::Vector3d(1.3, 0.8, 1.1).asDiagonal();
    b = Eigen::Vector3d(0.2, -0.1, 0.4);
  }
  const auto to_physical = [&](const Eigen::Vector3d& xi) -> Eigen::Vector3d { return A * xi + b; };
  const Eigen::MatrixXd corners = (reference_corners * A.transpose()).rowwise() + b.transpose();
  const CellGeometry cell(type, corners);
  // Shapes built in the corner frame s (origin at a cell corner, axes along its edges):
  // tets ξ = s, hexes ξ = 2 s − 1; the mirror image s_x ↦ −s_x lies outside, touching.
  const auto to_reference = [&](const Eigen::Vector3d& s) -> Eigen::Vector3d {
    return hexahedron ? Eigen::Vector3d(2.0 * s.array() - 1.0) : s;
  };
  const double size = 0.25;  // L-prism reaches 2·size = 0.5 < 1 along x and y
  for (const EmbeddedShape& shape : testing::corner_shapes(size)) {
    SCOPED_TRACE(shape.name);
    const EmbeddedShape inside =
        testing::mapped(shape, [&](const Eigen::Vector3d& s) { return to_physical(to_reference(s)); });
    const EmbeddedShape outside = testing::mapped(shape, [&](const Eigen::Vector3d& s) {
      return to_physical(to_reference(Eigen::Vector3d(-s.x(), s.y(), s.z())));
    });
    std::vector<TetrahedronCorners> tetrahedra = testing::corner_matrices(inside.tetrahedra);
    for (const auto& t : testing::corner_matrices(outside.tetrahedra)) tetrahedra.push_back(t);

    const int order = 3;
    const IntersectionRule intersection = intersection_rule(cell, tetrahedra, order);
    const Eigen::VectorXd exact = polyhedron_moments(inside.boundary, 1);  // 1, x, y, z
    const double length = std::cbrt(exact(0));
    const auto moments = [&](const QuadratureRule& rule) {
      Eigen::Vector4d sum = Eigen::Vector4d::Zero();
      for (Eigen::Index q = 0; q < rule.points.rows(); ++q) {
        const Eigen::Vector3d xi = rule.points.row(q).transpose();
        const double weight = rule.weights(q) * cell.jacobian_determinant(xi);
        const Eigen::Vector3d x = to_physical(xi);
        sum += weight * Eigen::Vector4d(1.0, x.x(), x.y(), x.z());
      }
      return sum;
    };
    const Eigen::Vector4d initial = moments(intersection.rule);
    // First moments relative to volume × (|centroid| + size): the convention's ∫|f| scale.
    const double scale = exact(0) * (exact.tail<3>().norm() / exact(0) + length);
    EXPECT_NEAR(initial(0), exact(0), 1e-13 * exact(0));
    EXPECT_NEAR(intersection.clipped_volume, exact(0), 1e-13 * exact(0));
    for (int d = 1; d < 4; ++d) EXPECT_NEAR(initial(d), exact(d), 1e-13 * scale) << "moment " << d;

    const IntersectionRule fewer = intersection_rule(cell, tetrahedra, order, PieceFan::vertex);
    EXPECT_LE(fewer.rule.points.rows(), intersection.rule.points.rows());
    EXPECT_NEAR(fewer.clipped_volume, exact(0), 1e-13 * exact(0));
    // Every monomial of degree <= order in physical coordinates scaled by the shape's size.
    const auto monomial_moment = [&](const QuadratureRule& rule, const Eigen::Vector3i& exponent) {
      double sum = 0.0;
      for (Eigen::Index q = 0; q < rule.points.rows(); ++q) {
        const Eigen::Vector3d xi = rule.points.row(q).transpose();
        const Eigen::Vector3d x = to_physical(xi) / length;
        sum += rule.weights(q) * cell.jacobian_determinant(xi) * std::pow(x.x(), exponent.x()) *
               std::pow(x.y(), exponent.y()) * std::pow(x.z(), exponent.z());
      }
      return sum;
    };
    for (int a = 0; a <= order; ++a)
      for (int b = 0; a + b <= order; ++b)
        for (int c = 0; a + b + c <= order; ++c) {
          const Eigen::Vector3i exponent(a, b, c);
          const double centroid_fan = monomial_moment(intersection.rule, exponent);
          const double scale_of_monomial = exact(0) * std::pow(2.0 + exact.tail<3>().norm() / exact(0) / length, order);
          EXPECT_NEAR(monomial_moment(fewer.rule, exponent), centroid_fan, 1e-13 * scale_of_monomial)
              << "x^" << a << " y^" << b << " z^" << c;
        }

    const SimplificationResult simplified =
        simplify_quadrature(intersection.rule, {order, SimplificationOptions{}.method, 1e-12});
    EXPECT_FALSE(simplified.failed);
    EXPECT_GT(simplified.rule.weights.minCoeff(), 0.0);
    const Eigen::Vector4d reduced = moments(simplified.rule);
    EXPECT_NEAR(reduced(0), exact(0), 1e-13 * exact(0));  // the cell's volume fraction
    for (int d = 1; d < 4; ++d) EXPECT_NEAR(reduced(d), exact(d), 1e-13 * scale) << "moment " << d;
  }
}

std::string case_name(const ::testing::TestParamInfo<CellCase>& info) {
  return std::string(element_name(info.param.type)) + (info.param.affine_map ? "_affine" : "_reference");
}

INSTANTIATE_TEST_SUITE_P(Cells, IntersectionMoments,
                         ::testing::Values(CellCase{ElementType::hex8, false}, CellCase{ElementType::hex20, false},
                                           CellCase{ElementType::hex27, false}, CellCase{ElementType::tet4, false},
                                           CellCase{ElementType::tet10, false}, CellCase{ElementType::hex20, true},
                                           CellCase{ElementType::tet10, true}),
                         case_name);

}  // namespace
}  // namespace altfem::fcm
