#include "polyhedral/mfs_least_squares.hpp"

#include <Eigen/QR>
#include <cmath>
#include <vector>

namespace altfem::harmonic {

namespace {

// Columns per block of the blocked Householder QR. Eigen's HouseholderQR uses 48; on
// the MFS systems (m ≈ 850, k ≈ 250) 16 or 24 factorise ~15% faster on one core (the
// level-2 panel work shrinks while the level-3 trailing updates stay large), 5-10% of a
// whole element basis (bench_polyhedral_element, harmonic_basis, alternating runs).
// OpenBLAS's dgeqrf + dormqr were ~40% slower than Eigen here (one thread, 860 × 222).
constexpr Eigen::Index qr_block_columns = 16;

}  // namespace

double solve_mfs_least_squares(Eigen::Ref<Eigen::MatrixXd> system, Eigen::Ref<Eigen::MatrixXd> data,
                               const std::function<void()>& refill, Eigen::MatrixXd& coefficients) {
  const Eigen::Index m = system.rows(), k = system.cols();
  const auto entries = static_cast<double>(data.size());
  // Householder QR in place; Qᵀ·data gives the coefficients from its top rows and the
  // misfit from the rest.
  Eigen::VectorXd householder(k), workspace(k);
  Eigen::internal::householder_qr_inplace_blocked<Eigen::Ref<Eigen::MatrixXd>, Eigen::VectorXd>::run(
      system, householder, qr_block_columns, workspace.data());
  const auto diagonal = system.diagonal().cwiseAbs();
  if (diagonal.minCoeff() > 1e-12 * diagonal.maxCoeff()) {
    data.applyOnTheLeft(Eigen::householderSequence(system, householder).transpose());
    coefficients = system.topRows(k).triangularView<Eigen::Upper>().solve(data.topRows(k));
    return std::sqrt(data.bottomRows(m - k).squaredNorm() / entries);
  }
  refill();
  coefficients = system.completeOrthogonalDecomposition().solve(data);
  return std::sqrt((system * coefficients - data).squaredNorm() / entries);
}

}  // namespace altfem::harmonic
