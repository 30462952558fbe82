#include "shared/cut_cells/cut_cell_rule.hpp"

#include <Eigen/LU>
#include <cmath>
#include <string>

#include "shared/common/error.hpp"
#include "shared/element/geometry_map.hpp"
#include "shared/element/reference_element.hpp"
#include "shared/quadrature/reference_rules.hpp"

namespace altfem {

CellGeometry::CellGeometry(ElementType type, const Eigen::Ref<const Eigen::MatrixXd>& corners)
    : type_(type),
      corner_type_(element_shape(type) == ElementShape::tetrahedron ? ElementType::tet4 : ElementType::hex8),
      corners_(corners) {
  if (corners_.rows() != element_corner_count(type) || corners_.cols() != 3) {
    throw std::invalid_argument("CellGeometry: corners must be #corners x 3");
  }
  if (corner_type_ == ElementType::tet4) {
    planes_ = tetrahedron_clip_planes(corners_);
    affine_ = true;
  } else {
    if (!hexahedron_faces_planar(corners_)) {
      throw NumericalError(
          "fcm: a hexahedral background cell has non-planar faces; intersection "
          "quadrature clips by the face planes");
    }
    planes_ = hexahedron_clip_planes(corners_);
    // The trilinear map is affine when its bilinear and trilinear coefficients
    // vanish: x0 − x1 + x2 − x3 (and the other two faces' twists) and the body term.
    const auto x = [&](int i) { return Eigen::Vector3d(corners_.row(i).transpose()); };
    const double size = (x(6) - x(0)).norm();
    const double twist = (x(0) - x(1) + x(2) - x(3)).norm() + (x(0) - x(1) + x(5) - x(4)).norm() +
                         (x(0) - x(3) + x(7) - x(4)).norm() +
                         (x(0) - x(1) + x(2) - x(3) - x(4) + x(5) - x(6) + x(7)).norm();
    affine_ = twist <= 1e-14 * size;
  }
  const ReferenceElement& element = reference_element(corner_type_);
  if (affine_) {
    origin_ = map_to_physical(element, corners_, Eigen::Vector3d::Zero());
    jacobian_ = map_jacobian(element, corners_, element.centroid());
    inverse_jacobian_ = jacobian_.inverse();
    determinant_ = std::abs(jacobian_.determinant());
  }
}

Eigen::Vector3d CellGeometry::to_reference(const Eigen::Vector3d& x) const {
  if (affine_) return inverse_jacobian_ * (x - origin_);
  const InverseMapResult inverse = map_to_reference(reference_element(corner_type_), corners_, x);
  if (!inverse.converged) {
    throw NumericalError("fcm: Newton did not invert a background cell's map at a quadrature point (residual " +
                         std::to_string(inverse.residual) + ")");
  }
  return inverse.xi;
}

double CellGeometry::jacobian_determinant(const Eigen::Vector3d& xi) const {
  if (affine_) return determinant_;
  return std::abs(map_jacobian(reference_element(corner_type_), corners_, xi).determinant());
}

double CellGeometry::volume() const {
  // det J of a trilinear map has degree <= 2 in each coordinate: strength 3 is exact.
  const QuadratureRule rule =
      reference_rule(corner_type_ == ElementType::tet4 ? ReferenceDomain::tetrahedron : ReferenceDomain::hexahedron, 3);
  double sum = 0.0;
  for (Eigen::Index q = 0; q < rule.points.rows(); ++q) {
    sum += rule.weights(q) * jacobian_determinant(rule.points.row(q).transpose());
  }
  return sum;
}

IntersectionRule intersection_rule(const CellGeometry& cell, const std::vector<TetrahedronCorners>& tetrahedra,
                                   int order, PieceFan fan) {
  const QuadratureRule tet = tet_rule(order);  // unit tet, weights sum to 1/6
  std::vector<TetrahedronCorners> pieces;
  for (const TetrahedronCorners& tetrahedron : tetrahedra) {
    std::vector<TetrahedronCorners> clipped = clip_tetrahedron(tetrahedron, cell.planes(), fan);
    pieces.insert(pieces.end(), clipped.begin(), clipped.end());
  }
  IntersectionRule result;
  const Eigen::Index per_piece = tet.points.rows();
  result.rule.points.resize(static_cast<Eigen::Index>(pieces.size()) * per_piece, 3);
  result.rule.weights.resize(result.rule.points.rows());
  result.rule.strength = order;
  Eigen::Index row = 0;
  for (const TetrahedronCorners& piece : pieces) {
    // T_Q(η) = q0 + [q1 − q0, q2 − q0, q3 − q0] η; |J_Q| = det of that matrix.
    const Eigen::Vector3d q0 = piece.row(0).transpose();
    const Eigen::Matrix3d edges = (piece.bottomRows<3>().rowwise() - piece.row(0)).transpose();
    const double piece_jacobian = edges.determinant();  // tetrahedron_jacobian(piece), edges formed once
    result.clipped_volume += piece_jacobian / 6.0;
    for (Eigen::Index q = 0; q < per_piece; ++q) {
      const Eigen::Vector3d xi = cell.to_reference(q0 + edges * tet.points.row(q).transpose());
      // Eq. (11): w = l_j |J_Q| / |J_K(ξ)|, so that Σ w f |J_K| = Σ l_j f |J_Q|.
      result.rule.points.row(row) = xi.transpose();
      result.rule.weights(row) = tet.weights(q) * piece_jacobian / cell.jacobian_determinant(xi);
      ++row;
    }
  }
  return result;
}

}  // namespace altfem
