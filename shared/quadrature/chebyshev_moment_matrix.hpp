#pragma once
// The moment matrix of a point set in a well-conditioned polynomial basis (Longva et
// al. 2020, §4.4.3, eq. (9)): tensor products of Chebyshev polynomials of the first
// kind, p_abc(x) = T_a(x̂) T_b(ŷ) T_c(ẑ) with a + b + c <= degree, where x̂ maps the
// points' bounding box onto [-1,1]³. Scaling to the box keeps the rows far from
// linearly dependent when the points cluster in a small part of a cell.
#include <Eigen/Core>

namespace altfem {

/// P (C(degree+3, 3) × #points): P(i, j) = p_i(point j), basis graded by total degree.
/// points: #points × 3. A box side of zero length is treated as length 1 (the
/// polynomials are then constant along it). Throws std::invalid_argument for degree < 0.
Eigen::MatrixXd chebyshev_moment_matrix(const Eigen::Ref<const Eigen::MatrixXd>& points, int degree);

}  // namespace altfem
