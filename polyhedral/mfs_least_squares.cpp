#include "polyhedral/mfs_least_squares.hpp"

#include <Eigen/QR>
#include <cmath>

namespace altfem::harmonic {

double solve_mfs_least_squares(Eigen::Ref<Eigen::MatrixXd> system, Eigen::Ref<Eigen::MatrixXd> data,
                               const std::function<void()>& refill, Eigen::MatrixXd& coefficients) {
  const Eigen::Index m = system.rows(), k = system.cols();
  const auto entries = static_cast<double>(data.size());
  // Qᵀ·data gives the coefficients from its top rows and the misfit from the rest.
  const Eigen::HouseholderQR<Eigen::Ref<Eigen::MatrixXd>> qr(system);
  const auto diagonal = qr.matrixQR().diagonal().cwiseAbs();
  if (diagonal.minCoeff() > 1e-12 * diagonal.maxCoeff()) {
    data.applyOnTheLeft(qr.householderQ().transpose());
    coefficients = qr.matrixQR().topRows(k).triangularView<Eigen::Upper>().solve(data.topRows(k));
    return std::sqrt(data.bottomRows(m - k).squaredNorm() / entries);
  }
  refill();
  coefficients = system.completeOrthogonalDecomposition().solve(data);
  return std::sqrt((system * coefficients - data).squaredNorm() / entries);
}

}  // namespace altfem::harmonic
