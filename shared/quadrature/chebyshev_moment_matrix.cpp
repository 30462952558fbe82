#include "shared/quadrature/chebyshev_moment_matrix.hpp"

#include <stdexcept>
#include <vector>

namespace altfem {

Eigen::MatrixXd chebyshev_moment_matrix(const Eigen::Ref<const Eigen::MatrixXd>& points, int degree) {
  if (degree < 0) throw std::invalid_argument("chebyshev_moment_matrix: degree must be >= 0");
  if (points.cols() != 3) throw std::invalid_argument("chebyshev_moment_matrix: points must be #points x 3");
  const Eigen::Index count = points.rows();
  const int basis_size = (degree + 1) * (degree + 2) * (degree + 3) / 6;
  Eigen::MatrixXd matrix(basis_size, count);
  if (count == 0) return matrix;

  const Eigen::RowVector3d low = points.colwise().minCoeff(), high = points.colwise().maxCoeff();
  const Eigen::RowVector3d centre = 0.5 * (low + high);
  Eigen::RowVector3d half_size = 0.5 * (high - low);
  for (int d = 0; d < 3; ++d) {
    if (!(half_size(d) > 0.0)) half_size(d) = 1.0;
  }

  // T_k(x̂) per axis by the three-term recurrence, then the products in graded order
  // (degree q, then b + c, then c: the order of monomial_index). Plain arrays: this
  // runs for every point of every cut cell.
  const int values = degree + 1;
  std::vector<double> chebyshev(3 * static_cast<std::size_t>(values));  // axis d: [d * values, (d + 1) * values)
  for (Eigen::Index j = 0; j < count; ++j) {
    for (int d = 0; d < 3; ++d) {
      double* t = chebyshev.data() + d * values;
      const double x = (points(j, d) - centre(d)) / half_size(d);
      t[0] = 1.0;
      if (degree >= 1) t[1] = x;
      // 2 (x T_{k-1}) − T_{k-2}: the doubling is exact, so the value does not depend on
      // whether the compiler fuses the subtraction (results stay bit-identical).
      for (int k = 2; k <= degree; ++k) t[k] = 2.0 * (x * t[k - 1]) - t[k - 2];
    }
    const double *tx = chebyshev.data(), *ty = tx + values, *tz = ty + values;
    double* column = matrix.col(j).data();
    for (int q = 0; q <= degree; ++q) {
      for (int transverse = 0; transverse <= q; ++transverse) {
        const double x_part = tx[q - transverse];
        for (int c = 0; c <= transverse; ++c) *column++ = x_part * ty[transverse - c] * tz[c];
      }
    }
  }
  return matrix;
}

}  // namespace altfem
