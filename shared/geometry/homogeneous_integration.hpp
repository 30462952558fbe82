#pragma once
// Exact monomial integrals over segments and planar polygons by homogeneous-function
// integration (Chin, Lasserre & Sukumar 2015, "Numerical integration of homogeneous
// functions on convex and nonconvex polygons and polyhedra", Comput. Mech. 56:967–981):
// Euler's identity x·∇f = q f for f homogeneous of degree q turns the divergence theorem
// into a recursion from a polytope to its facets, exact for convex and non-convex shapes
// and any degree. These kernels work in the coordinates they are given (no recentring):
// call them in a frame where the shape is of size ~1 near the origin (MomentFrame), as
// polygon_moments and polyhedron_moments do.
#include <Eigen/Core>

namespace altfem {

/// ∫_0^1 (start + t·(end − start))^α dt for every α of degree <= `degree` in 2D, i.e. the
/// mean of each monomial over the segment; length monomial_count_2d(degree),
/// monomial_index_2d order.
Eigen::VectorXd segment_moments_2d(const Eigen::Vector2d& start, const Eigen::Vector2d& end, int degree);

/// ∫_F x^α dσ over the planar polygon F with vertices `face` (#vertices × 3, >= 3,
/// counter-clockwise about `unit_normal`, simple, convex or not), for every α of degree
/// <= `degree`; length monomial_count(degree).
Eigen::VectorXd planar_face_moments(const Eigen::MatrixXd& face, const Eigen::Vector3d& unit_normal, int degree);

}  // namespace altfem
