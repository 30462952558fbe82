#pragma once
// Change of centre and scale for monomial moments: how moments computed in a
// well-conditioned frame (centred at the body, scaled by its size) become the moments
// a caller asked for (raw, or about a DG element's own centre and scale).
#include <Eigen/Core>

namespace altfem {

/// The frame in which moments of a body are computed before shifting: the centre of the
/// bounding box of its vertices and half the box's longest side, so that the body lies
/// in [-1,1]^dim and the divergence-theorem sums do not cancel (the homogeneous-function
/// formulas weight each face by its distance to the origin).
struct MomentFrame {
  Eigen::VectorXd centre;  ///< dim
  double scale = 1.0;      ///< > 0
};

/// points: #points × dim. Throws std::invalid_argument if there are no points, a
/// coordinate is not finite, or all points coincide.
MomentFrame bounding_box_frame(const Eigen::MatrixXd& points);

/// (points − centre) / scale, row by row: #points × dim.
Eigen::MatrixXd local_coordinates(const MomentFrame& frame, const Eigen::MatrixXd& points);

/// The moments ∫ ((x − centre)/scale)^α of a body, from its moments in `frame`,
/// ∫ ((x − frame.centre)/frame.scale)^α, both in the physical measure: shift_moments (2D or
/// 3D by the frame's dimension) with offset (frame.centre − centre)/scale and ratio
/// frame.scale/scale. centre: dim. Throws std::invalid_argument unless scale is finite and > 0.
Eigen::VectorXd moments_about(const Eigen::VectorXd& frame_moments, int degree, const MomentFrame& frame,
                              const Eigen::VectorXd& centre, double scale);

/// Moments of (offset + ratio·ξ)^α for every α of total degree <= `degree`, given the
/// moments of ξ^α; both vectors have length monomial_count(degree), in the order of
/// monomial_index.hpp. Stable when the ξ frame is centred at the body and |offset| is not
/// much larger than ratio·(body size in ξ), or when moving outward to a far centre; moving
/// from a far frame to a near one (raw moments → moments about the body) cancels
/// catastrophically: compute in a near frame instead. Throws std::invalid_argument for
/// degree < 0 or a wrong length.
Eigen::VectorXd shift_moments(const Eigen::VectorXd& moments, int degree, const Eigen::Vector3d& offset, double ratio);

/// The same in 2D (length monomial_count_2d(degree), order of monomial_index_2d).
Eigen::VectorXd shift_moments_2d(const Eigen::VectorXd& moments, int degree, const Eigen::Vector2d& offset,
                                 double ratio);

}  // namespace altfem
