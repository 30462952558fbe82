#pragma once
// Two-dimensional harmonic coordinates of one planar polygonal face (Martin et al.
// 2008 §4-5): for each node i of the face, the harmonic function in the face's plane
// whose boundary values are 1 at node i, 0 at the other nodes, and linear along each
// edge. They are the boundary data of the element's 3D basis, and since two elements
// sharing a face compute them from the same polygon, the same on both sides.
//
// MFS, eq. (11) in 2D: N(x) = Σ_j w_j log‖x − k_j‖ + a·x + a₀ in a local frame of the
// plane, fitted in the least-squares sense (eq. (14)) to the boundary data at m ≈ 3n
// collocation points; the linear polynomial makes linear reproduction exact. One
// factorisation serves every node's right-hand side. Triangles and rectangles take their
// closed-form coordinates (barycentric, bilinear) instead, without kernels.
#include <Eigen/Core>

#include "polyhedral/mfs_options.hpp"

namespace altfem::harmonic {

class FaceHarmonicCoordinates {
public:
  /// polygon: #nodes × 3, the face's nodes in boundary order (convex or not, planar;
  /// nodes may lie on straight edges, e.g. a finer neighbour's nodes).
  FaceHarmonicCoordinates(const Eigen::MatrixXd& polygon, const MfsOptions& options);

  int node_count() const { return static_cast<int>(polygon_.rows()); }
  /// The coordinates at points of the face's plane: #points × #nodes (points: #points × 3).
  Eigen::MatrixXd evaluate(const Eigen::MatrixXd& points) const;
  /// Their gradients at one point of the plane, in the plane: #nodes × 3 (row i: ∇N_i),
  /// from ∇ log‖x − k‖ = (x − k)/‖x − k‖² (the 2D Poisson example's stiffness).
  Eigen::MatrixX3d gradients(const Eigen::Vector3d& point) const;

private:
  Eigen::MatrixX2d to_plane(const Eigen::MatrixXd& points) const;  // local, scaled coordinates
  // The MFS functions at local points (#points × 2): rows (#points × (#centres +
  // polynomial_count())) of log‖x − k_j‖, then x, y, 1, and xy on a rectangle.
  void kernel_rows(const Eigen::MatrixX2d& local, Eigen::Ref<Eigen::MatrixXd> rows) const;
  Eigen::Index polynomial_count() const { return bilinear_ ? 4 : 3; }

  Eigen::MatrixXd polygon_;
  Eigen::Vector3d origin_, axis_u_, axis_v_;
  double scale_ = 1;
  bool bilinear_ = false;         // a rectangle: the bilinear coordinates, no kernels
  Eigen::MatrixX2d centres_;      // #centres × 2, local
  Eigen::MatrixXd coefficients_;  // (#centres + 3) × #nodes
};

}  // namespace altfem::harmonic
