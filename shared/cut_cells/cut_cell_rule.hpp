#pragma once
// Intersection quadrature for one background cell (Longva et al. 2020, §4.5): clip
// every candidate tetrahedron of the embedded mesh by the cell, tetrahedralise the
// convex pieces, put a degree-m tetrahedron rule on each piece and map its points back
// to the cell's reference domain with the weights of eqs. (11)–(12).
#include <Eigen/Core>
#include <vector>

#include "shared/element/element_type.hpp"
#include "shared/geometry/clip_convex.hpp"
#include "shared/quadrature/quadrature_rule.hpp"

namespace altfem {

/// The geometry of a background cell: its corner map (affine for tetrahedra,
/// trilinear for hexahedra; higher-order nodes are not used) of a cell of `type`.
class CellGeometry {
public:
  /// corners: 4 × 3 (tets) or 8 × 3 (hexes), VTK order, positively oriented. A
  /// hexahedron must have exactly planar faces (clipping is by its face planes):
  /// throws NumericalError otherwise.
  CellGeometry(ElementType type, const Eigen::Ref<const Eigen::MatrixXd>& corners);

  ElementType type() const { return type_; }
  const Eigen::MatrixXd& corners() const { return corners_; }
  const std::vector<ClipPlane>& planes() const { return planes_; }
  /// ξ with x(ξ) = x (Newton on the trilinear map unless it is affine); throws
  /// NumericalError if Newton fails.
  Eigen::Vector3d to_reference(const Eigen::Vector3d& x) const;
  /// |det ∂x/∂ξ| at ξ.
  double jacobian_determinant(const Eigen::Vector3d& xi) const;
  /// The cell's volume (exact for the corner map).
  double volume() const;
  /// Whether the corner map is affine (every tetrahedron; a hexahedron that is a parallelepiped).
  bool affine() const { return affine_; }

private:
  ElementType type_;
  ElementType corner_type_;  ///< tet4 or hex8: the corner map's element
  Eigen::MatrixXd corners_;
  std::vector<ClipPlane> planes_;
  bool affine_ = false;
  Eigen::Vector3d origin_;    ///< x(ξ = 0) when affine
  Eigen::Matrix3d jacobian_;  ///< ∂x/∂ξ when affine
  Eigen::Matrix3d inverse_jacobian_;
  double determinant_ = 0;  ///< |det jacobian_| when affine (every point of a rule asks for it)
};

/// |J_Q| of a tetrahedron's map from the unit one, q0 + [q1 − q0, q2 − q0, q3 − q0] η:
/// six times its volume, positive for the clip's positively oriented pieces.
/// (The same product intersection_rule forms for the piece's map, so both sum the same volumes.)
inline double tetrahedron_jacobian(const TetrahedronCorners& corners) {
  const Eigen::Matrix3d edges = (corners.bottomRows<3>().rowwise() - corners.row(0)).transpose();
  return edges.determinant();
}

struct IntersectionRule {
  QuadratureRule rule;          ///< points #points × 3 in the cell's reference domain; ∫ f ≈ Σ w f(ξ)|J_K(ξ)|
  double clipped_volume = 0.0;  ///< physical volume of the clipped pieces (Σ |J_Q| / 6)
};

/// The rule of eqs. (11)–(12) for cell ∩ (union of `tetrahedra`), exact for polynomials
/// of degree `order` in physical coordinates when the cell map is affine. The
/// tetrahedra (each 4 × 3 corners) must not overlap; candidates that miss the cell
/// contribute nothing. `fan`: how each clipped piece is tetrahedralised (clip_tetrahedron).
IntersectionRule intersection_rule(const CellGeometry& cell, const std::vector<TetrahedronCorners>& tetrahedra,
                                   int order, PieceFan fan = PieceFan::centroid);

}  // namespace altfem
