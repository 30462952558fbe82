#include "polyhedral/mfs_least_squares.hpp"

#include <Eigen/QR>
#include <algorithm>
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

double solve_mfs_least_squares(Eigen::Ref<Eigen::MatrixXd> augmented, Eigen::Index unknowns,
                               const std::function<void()>& refill, Eigen::MatrixXd& coefficients) {
  const Eigen::Index m = augmented.rows(), k = unknowns, nodes = augmented.cols() - unknowns;
  const auto entries = static_cast<double>(m * nodes);
  // Householder QR of [A | B] in place: R = [R_AA R_AB; 0 R_BB], where R_AB is the top of
  // Qᵀ·B (the coefficients solve R_AA x = R_AB) and R_BB carries the norm of the rest
  // (the misfit: the later reflectors act on rows ≥ k only, keeping their norms). Joint
  // instead of QR of A and then Qᵀ applied to B: ~12% less time on 850 × (250 + 22).
  Eigen::VectorXd householder(augmented.cols()), workspace(augmented.cols());
  Eigen::internal::householder_qr_inplace_blocked<Eigen::Ref<Eigen::MatrixXd>, Eigen::VectorXd>::run(
      augmented, householder, qr_block_columns, workspace.data());
  const auto diagonal = augmented.topLeftCorner(k, k).diagonal().cwiseAbs();
  if (diagonal.minCoeff() > 1e-12 * diagonal.maxCoeff()) {
    coefficients = augmented.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(augmented.topRightCorner(k, nodes));
    // R_BB: upper trapezoidal (below its diagonal lie the reflectors of B's columns).
    const auto remainder = augmented.bottomRightCorner(m - k, nodes);
    double misfit = 0;
    for (Eigen::Index j = 0; j < nodes; ++j) misfit += remainder.col(j).head(std::min(j + 1, m - k)).squaredNorm();
    return std::sqrt(misfit / entries);
  }
  refill();
  const auto system = augmented.leftCols(k);
  const auto data = augmented.rightCols(nodes);
  coefficients = Eigen::MatrixXd(system).completeOrthogonalDecomposition().solve(data);
  return std::sqrt((system * coefficients - data).squaredNorm() / entries);
}

}  // namespace altfem::harmonic
