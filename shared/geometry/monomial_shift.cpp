#include "shared/geometry/monomial_shift.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "shared/geometry/monomial_index.hpp"

namespace altfem {
namespace {

// (offset_k + ratio·ξ_k)^α_k = Σ_i C(α_k, i) offset_k^(α_k−i) ratio^i ξ_k^i. The product over
// axes factorises, so the expansion is applied one axis at a time: each pass costs
// #monomials × (degree+1) instead of #monomials × Π_k (α_k+1).
template <int D>
Eigen::VectorXd shift(const Eigen::VectorXd& moments, int degree, const Eigen::Matrix<double, D, 1>& offset,
                      double ratio, const Eigen::Matrix<int, Eigen::Dynamic, D>& exponents) {
  if (moments.size() != exponents.rows()) {
    throw std::invalid_argument("shift_moments: expected " + std::to_string(exponents.rows()) + " moments for degree " +
                                std::to_string(degree) + ", got " + std::to_string(moments.size()));
  }
  Eigen::MatrixXd binomial = Eigen::MatrixXd::Zero(degree + 1, degree + 1);
  for (int n = 0; n <= degree; ++n) {
    binomial(n, 0) = 1.0;
    for (int i = 1; i <= n; ++i) binomial(n, i) = binomial(n - 1, i - 1) + binomial(n - 1, i);  // C(n−1, n) = 0
  }
  Eigen::VectorXd ratio_power(degree + 1);
  ratio_power(0) = 1.0;
  for (int i = 1; i <= degree; ++i) ratio_power(i) = ratio_power(i - 1) * ratio;

  Eigen::VectorXd current = moments;
  for (int axis = 0; axis < D; ++axis) {
    Eigen::VectorXd offset_power(degree + 1);
    offset_power(0) = 1.0;
    for (int i = 1; i <= degree; ++i) offset_power(i) = offset_power(i - 1) * offset(axis);
    Eigen::VectorXd next(current.size());
    for (Eigen::Index row = 0; row < exponents.rows(); ++row) {
      Eigen::Matrix<int, 1, D> beta = exponents.row(row);
      const int power = beta(axis);
      double sum = 0.0;
      for (int i = 0; i <= power; ++i) {
        beta(axis) = i;
        sum += binomial(power, i) * offset_power(power - i) * ratio_power(i) * current(monomial_index(beta));
      }
      next(row) = sum;
    }
    current = std::move(next);
  }
  return current;
}

}  // namespace

MomentFrame bounding_box_frame(const Eigen::MatrixXd& points) {
  if (points.rows() == 0) throw std::invalid_argument("moments: expected at least one vertex, got none");
  if (!points.allFinite()) throw std::invalid_argument("moments: expected finite vertex coordinates, got NaN or inf");
  const Eigen::RowVectorXd low = points.colwise().minCoeff();
  const Eigen::RowVectorXd high = points.colwise().maxCoeff();
  const double scale = 0.5 * (high - low).maxCoeff();
  if (!(scale > 0.0)) throw std::invalid_argument("moments: expected vertices spanning a region, got all coincident");
  return {0.5 * (low + high).transpose(), scale};
}

Eigen::VectorXd shift_moments(const Eigen::VectorXd& moments, int degree, const Eigen::Vector3d& offset, double ratio) {
  return shift<3>(moments, degree, offset, ratio, monomial_exponents(degree));
}

Eigen::VectorXd shift_moments_2d(const Eigen::VectorXd& moments, int degree, const Eigen::Vector2d& offset,
                                 double ratio) {
  return shift<2>(moments, degree, offset, ratio, monomial_exponents_2d(degree));
}

Eigen::MatrixXd local_coordinates(const MomentFrame& frame, const Eigen::MatrixXd& points) {
  return (points.rowwise() - frame.centre.transpose()) / frame.scale;
}

Eigen::VectorXd moments_about(const Eigen::VectorXd& frame_moments, int degree, const MomentFrame& frame,
                              const Eigen::VectorXd& centre, double scale) {
  if (!(scale > 0.0) || !std::isfinite(scale)) {
    throw std::invalid_argument("moments: expected a finite scale > 0, got " + std::to_string(scale));
  }
  const Eigen::VectorXd offset = (frame.centre - centre) / scale;
  const double ratio = frame.scale / scale;
  if (frame.centre.size() == 2) return shift_moments_2d(frame_moments, degree, offset.head<2>(), ratio);
  return shift_moments(frame_moments, degree, offset.head<3>(), ratio);
}

}  // namespace altfem
