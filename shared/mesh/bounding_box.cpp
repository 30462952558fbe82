#include "shared/mesh/bounding_box.hpp"

namespace altfem {

BoundingBox bounding_box(const Eigen::MatrixXd& points) {
  BoundingBox box;
  if (points.rows() == 0) return box;
  // A row loop rather than colwise().minCoeff(): GCC 12 with -march=native reports a
  // false -Wmaybe-uninitialized inside Eigen's AVX-512 column reduction.
  box.minimum = box.maximum = points.row(0).transpose();
  for (Eigen::Index i = 1; i < points.rows(); ++i) {
    box.minimum = box.minimum.cwiseMin(points.row(i).transpose());
    box.maximum = box.maximum.cwiseMax(points.row(i).transpose());
  }
  return box;
}

}  // namespace altfem
