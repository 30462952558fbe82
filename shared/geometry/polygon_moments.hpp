#pragma once
// Exact integrals of every monomial up to a degree over polygons: in the plane, and
// planar polygons in 3D (DG face terms). Any degree; convex or not.
#include <Eigen/Core>

namespace altfem {

/// ∫_P x^a y^b dA over the simple polygon P (polygon: #vertices × 2, >= 3, convex or
/// not) for every a+b <= degree, in monomial_index_2d order. Signed like the shoelace
/// formula: counter-clockwise gives the moments, clockwise their negation.
/// Throws std::invalid_argument for bad input (degree < 0, < 3 vertices, not finite).
Eigen::VectorXd polygon_moments_2d(const Eigen::MatrixXd& polygon, int degree);

/// ∫_P ((x−c)/s)^a ((y−c)/s)^b dA (physical area measure), the moments a monomial basis
/// centred at `centre` and scaled by `scale` > 0 needs.
Eigen::VectorXd polygon_moments_2d(const Eigen::MatrixXd& polygon, int degree, const Eigen::Vector2d& centre,
                                   double scale);

/// ∫_F x^a y^b z^c dσ over the planar simple polygon F in 3D (polygon: #vertices × 3, >= 3,
/// convex or not) for every a+b+c <= degree, in monomial_index order; surface measure, so
/// independent of the vertex orientation. A polygon of zero area has zero moments.
Eigen::VectorXd planar_polygon_moments(const Eigen::MatrixXd& polygon, int degree);

/// ∫_F ((x−c)/s)^α dσ (physical area measure) for a basis centred at `centre`, scaled by `scale` > 0.
Eigen::VectorXd planar_polygon_moments(const Eigen::MatrixXd& polygon, int degree, const Eigen::Vector3d& centre,
                                       double scale);

/// Newell's area vector ½ Σ v_i × v_{i+1} of a polygon (#vertices × 3): its area times
/// its unit normal, right-handed about the vertex order; exact for planar polygons,
/// convex or not, and the least-squares plane normal for slightly warped ones.
Eigen::Vector3d polygon_area_vector(const Eigen::MatrixXd& polygon);

}  // namespace altfem
