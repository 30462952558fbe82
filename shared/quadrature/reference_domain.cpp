#include "shared/quadrature/reference_domain.hpp"

#include <cmath>

namespace altfem {

bool strictly_inside(ReferenceDomain domain, const Eigen::MatrixXd& points) {
  const bool box = domain == ReferenceDomain::quadrilateral || domain == ReferenceDomain::hexahedron;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    double coordinate_sum = 0.0;
    for (Eigen::Index d = 0; d < points.cols(); ++d) {
      const double x = points(i, d);
      if (box ? !(std::abs(x) < 1.0) : !(x > 0.0)) return false;
      coordinate_sum += x;
    }
    if (!box && !(coordinate_sum < 1.0)) return false;
  }
  return true;
}

}  // namespace altfem
