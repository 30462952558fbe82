#include "shared/quadrature/chebyshev_moment_matrix.hpp"

#include <stdexcept>

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
  // (degree q, then b + c, then c: the order of monomial_index).
  Eigen::MatrixXd chebyshev(degree + 1, 3);
  for (Eigen::Index j = 0; j < count; ++j) {
    const Eigen::RowVector3d scaled = (points.row(j) - centre).cwiseQuotient(half_size);
    chebyshev.row(0).setOnes();
    if (degree >= 1) chebyshev.row(1) = scaled;
    for (int k = 2; k <= degree; ++k) {
      chebyshev.row(k) = 2.0 * scaled.cwiseProduct(chebyshev.row(k - 1)) - chebyshev.row(k - 2);
    }
    int row = 0;
    for (int q = 0; q <= degree; ++q) {
      for (int transverse = 0; transverse <= q; ++transverse) {
        for (int c = 0; c <= transverse; ++c) {
          const int b = transverse - c, a = q - transverse;
          matrix(row++, j) = chebyshev(a, 0) * chebyshev(b, 1) * chebyshev(c, 2);
        }
      }
    }
  }
  return matrix;
}

}  // namespace altfem
