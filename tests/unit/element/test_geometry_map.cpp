// The isoparametric map: affine elements reproduce x = Aξ + b exactly, the
// Jacobian matches finite differences, and map_to_reference inverts
// map_to_physical on curved elements and flags points outside.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <random>
#include <stdexcept>

#include "shared/element/geometry_map.hpp"
#include "tests/unit/element/random_reference_points.hpp"

namespace altfem {
namespace {

using testing::all_element_types;
using testing::random_reference_points;

struct Affine {
  Eigen::Matrix3d matrix;
  Eigen::Vector3d offset;
};

/// A random, well-conditioned, orientation-preserving affine map (a distorted element).
Affine random_affine(unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Affine affine;
  for (int i = 0; i < 3; ++i) {
    affine.offset[i] = 5.0 * unit(generator);
    for (int j = 0; j < 3; ++j) affine.matrix(i, j) = (i == j ? 1.0 : 0.0) + 0.3 * unit(generator);
  }
  EXPECT_GT(affine.matrix.determinant(), 0.1);
  return affine;
}

/// #nodes × 3: the reference nodes under the affine map.
Eigen::MatrixXd affine_nodes(const ReferenceElement& element, const Affine& affine) {
  return (element.nodes() * affine.matrix.transpose()).rowwise() + affine.offset.transpose();
}

/// An affine element whose non-corner nodes (all nodes for Hex8) are moved by up
/// to `amplitude` in each coordinate: a curved (non-affine) element.
Eigen::MatrixXd curved_nodes(const ReferenceElement& element, unsigned seed, double amplitude) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Eigen::MatrixXd nodes = affine_nodes(element, random_affine(seed + 1));
  const int first_moved = element.type() == ElementType::hex8 ? 0 : element_corner_count(element.type());
  for (int i = first_moved; i < element.node_count(); ++i)
    for (int d = 0; d < 3; ++d) nodes(i, d) += amplitude * unit(generator);
  return nodes;
}

TEST(GeometryMap, AffineElementsReproduceTheAffineMap) {
  for (ElementType type : all_element_types) {
    const ReferenceElement& element = reference_element(type);
    const Affine affine = random_affine(3 + static_cast<unsigned>(type));
    const Eigen::MatrixXd nodes = affine_nodes(element, affine);
    for (const Eigen::Vector3d& xi : random_reference_points(type, 10, 17, -0.3)) {
      const Eigen::Vector3d x = affine.matrix * xi + affine.offset;
      EXPECT_LT((map_to_physical(element, nodes, xi) - x).norm(), 1e-12) << element_name(type);
      EXPECT_LT((map_jacobian(element, nodes, xi) - affine.matrix).norm(), 1e-12) << element_name(type);

      const InverseMapResult inverse = map_to_reference(element, nodes, x);
      EXPECT_TRUE(inverse.converged) << element_name(type);
      EXPECT_EQ(inverse.iterations, 1) << element_name(type) << ": an affine map needs one step";
      EXPECT_LT((inverse.xi - xi).norm(), 1e-12) << element_name(type);
      EXPECT_EQ(inverse.inside, element.contains(xi, 0.0)) << element_name(type);
    }
  }
}

// affine_jacobian finds the map's matrix on affine elements of every type and declines
// once one node leaves the affine position by more than its tolerance (curved Hex8 too:
// its trilinear map is affine only on parallelepipeds).
TEST(GeometryMap, AffineJacobianIsTheMatrixOfAffineElementsOnly) {
  for (ElementType type : all_element_types) {
    const ReferenceElement& element = reference_element(type);
    const Affine affine = random_affine(43 + static_cast<unsigned>(type));
    Eigen::MatrixXd nodes = affine_nodes(element, affine);
    const std::optional<Eigen::Matrix3d> jacobian = affine_jacobian(element, nodes);
    ASSERT_TRUE(jacobian.has_value()) << element_name(type);
    EXPECT_LT((*jacobian - affine.matrix).norm(), 1e-13) << element_name(type);
    if (type == ElementType::tet4) continue;     // any four points span an affine map
    nodes(element.node_count() - 1, 1) += 1e-9;  // far above 1e-12 of the extent
    EXPECT_FALSE(affine_jacobian(element, nodes).has_value()) << element_name(type);
    EXPECT_FALSE(affine_jacobian(element, curved_nodes(element, 47, 0.05)).has_value()) << element_name(type);
  }
}

TEST(GeometryMap, JacobianMatchesCentralFiniteDifferences) {
  const double h = 1e-6;
  for (ElementType type : all_element_types) {
    const ReferenceElement& element = reference_element(type);
    const Eigen::MatrixXd nodes = curved_nodes(element, 23, 0.1);
    for (const Eigen::Vector3d& xi : random_reference_points(type, 10, 29)) {
      Eigen::Matrix3d finite_differences;
      for (int j = 0; j < 3; ++j) {
        const Eigen::Vector3d offset = h * Eigen::Vector3d::Unit(j);
        finite_differences.col(j) =
            (map_to_physical(element, nodes, xi + offset) - map_to_physical(element, nodes, xi - offset)) / (2.0 * h);
      }
      const Eigen::Matrix3d jacobian = map_jacobian(element, nodes, xi);
      EXPECT_LT((finite_differences - jacobian).norm(), 1e-7 * jacobian.norm()) << element_name(type);
    }
  }
}

TEST(GeometryMap, InverseOfCurvedElementsRecoversTheReferencePoint) {
  for (ElementType type :
       {ElementType::tet10, ElementType::tet20, ElementType::hex8, ElementType::hex20, ElementType::hex27}) {
    const ReferenceElement& element = reference_element(type);
    const Eigen::MatrixXd nodes = curved_nodes(element, 31 + static_cast<unsigned>(type), 0.08);
    for (const Eigen::Vector3d& xi : random_reference_points(type, 20, 37, 0.01)) {
      const InverseMapResult inverse = map_to_reference(element, nodes, map_to_physical(element, nodes, xi));
      EXPECT_TRUE(inverse.converged) << element_name(type);
      EXPECT_TRUE(inverse.inside) << element_name(type);
      EXPECT_GT(inverse.iterations, 1) << element_name(type) << ": the map is not affine";
      EXPECT_LT((inverse.xi - xi).norm(), 1e-12) << element_name(type) << " at " << xi.transpose();
      EXPECT_LT(inverse.residual, 1e-12) << element_name(type);
    }
  }
}

TEST(GeometryMap, PointsOutsideCurvedElementsAreFlaggedAndExtrapolated) {
  for (ElementType type : {ElementType::tet10, ElementType::hex20, ElementType::hex27}) {
    const ReferenceElement& element = reference_element(type);
    const Eigen::MatrixXd nodes = curved_nodes(element, 41, 0.08);
    const Eigen::Vector3d outside = element.shape() == ElementShape::tetrahedron
                                        ? Eigen::Vector3d(0.55, 0.45, 0.15)  // beyond the face x+y+z=1
                                        : Eigen::Vector3d(1.2, 0.3, -0.5);   // beyond x=+1
    ASSERT_FALSE(element.contains(outside, 0.0));
    const InverseMapResult inverse = map_to_reference(element, nodes, map_to_physical(element, nodes, outside));
    EXPECT_TRUE(inverse.converged) << element_name(type);
    EXPECT_FALSE(inverse.inside) << element_name(type);
    EXPECT_LT((inverse.xi - outside).norm(), 1e-12) << element_name(type);

    // Far away, whatever Newton does, the point is not inside.
    const Eigen::Vector3d far = nodes.row(0).transpose() + Eigen::Vector3d(100.0, -40.0, 70.0);
    EXPECT_FALSE(map_to_reference(element, nodes, far).inside) << element_name(type);
  }
}

TEST(GeometryMap, DegenerateElementIsReportedNotThrown) {
  const ReferenceElement& element = reference_element(ElementType::hex8);
  const Eigen::MatrixXd collapsed = Eigen::MatrixXd::Zero(8, 3);
  const InverseMapResult inverse = map_to_reference(element, collapsed, Eigen::Vector3d(1.0, 2.0, 3.0));
  EXPECT_FALSE(inverse.converged);
  EXPECT_FALSE(inverse.inside);
}

TEST(GeometryMap, WrongNodeArrayShapeThrows) {
  const ReferenceElement& element = reference_element(ElementType::tet10);
  const Eigen::MatrixXd too_few = Eigen::MatrixXd::Zero(4, 3);
  EXPECT_THROW(map_to_physical(element, too_few, Eigen::Vector3d::Zero()), std::invalid_argument);
  EXPECT_THROW(map_jacobian(element, too_few, Eigen::Vector3d::Zero()), std::invalid_argument);
  EXPECT_THROW(map_to_reference(element, too_few, Eigen::Vector3d::Zero()), std::invalid_argument);
}

}  // namespace
}  // namespace altfem
