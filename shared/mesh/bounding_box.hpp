#pragma once
// The axis-aligned bounding box of a point set (scene facts, surface-error normalisation).
#include <Eigen/Core>

namespace altfem {

struct BoundingBox {
  Eigen::Vector3d minimum = Eigen::Vector3d::Zero();
  Eigen::Vector3d maximum = Eigen::Vector3d::Zero();
  /// Length of the diagonal, maximum − minimum.
  double diagonal() const { return (maximum - minimum).norm(); }
};

/// Bounding box of `points` (#points × 3); all zeros for no points.
BoundingBox bounding_box(const Eigen::MatrixXd& points);

}  // namespace altfem
