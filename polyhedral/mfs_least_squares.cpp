#include "polyhedral/mfs_least_squares.hpp"

#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace altfem::harmonic {

namespace {

// Columns per block of the blocked Householder QR. Eigen's HouseholderQR uses 48; on
// the MFS systems (m ≈ 850, k ≈ 250) 16 or 24 factorise ~15% faster on one core (the
// level-2 panel work shrinks while the level-3 trailing updates stay large), 5-10% of a
// whole element basis (bench_polyhedral_element, harmonic_basis, alternating runs).
// OpenBLAS's dgeqrf + dormqr were ~40% slower than Eigen here (one thread, 860 × 222).
constexpr Eigen::Index qr_block_columns = 16;
// The normal equations are tried first and kept when the Cholesky factor's pivots stay
// within this ratio (≈ 1/κ of the column-scaled system): then κ² u ≲ 1e-6 and one
// refinement step brings the solution to QR's accuracy. Below it the QR path below runs.
// Measured (bunny 16³, 784 cut cells, 4 samples/edge): half of the cells' pivot ratios lie
// below 4e-5, a tenth below 1e-5, 1% below 2e-6; with 1e-5 the partition of unity and
// linear reproduction at a strength-4 rule's points are QR's (max |ΣN − 1| 2.3e-11 against
// 2.7e-11, linear 3.0e-10 against 2.6e-10); with 1e-7, or without the refinement step,
// they grew to 1e-9–2e-7.
constexpr double normal_equations_pivot_ratio = 1e-5;
// Rows per symmetric rank update of the Gram matrix: Eigen packs each update's operands
// into fresh heap blocks, which above glibc's mmap threshold (128 KiB) come as new pages
// every call (page faults were a third of the solve on 860-row systems); 128 rows keep
// them small.
constexpr Eigen::Index gram_rows_per_update = 128;

// The least squares by the normal equations: the lower triangle of [A | B]ᵀ[A | B] by
// symmetric rank updates (m (k + #nodes)² flops, against QR's 2 m (k + #nodes)²), AᵀA
// scaled to a unit diagonal (column equilibration) and Cholesky-factored in place, then
// one step of iterative refinement on the true residual B − A x. Returns the RMS misfit,
// or nullopt (coefficients untouched, `augmented` unchanged) when the factor fails or its
// pivots fall below normal_equations_pivot_ratio.
std::optional<double> solve_by_normal_equations(const Eigen::Ref<const Eigen::MatrixXd>& augmented, Eigen::Index k,
                                                Eigen::MatrixXd& coefficients) {
  const Eigen::Index m = augmented.rows(), nodes = augmented.cols() - k;
  // A per-thread buffer that only grows (like the element's system): a Gram matrix of
  // ~270² is not returned to the system and faulted in again element after element.
  thread_local std::vector<double, Eigen::aligned_allocator<double>> storage;
  storage.resize(std::max(storage.size(), static_cast<size_t>((k + nodes) * (k + nodes))));
  Eigen::Map<Eigen::MatrixXd> gram(storage.data(), k + nodes, k + nodes);
  gram.setZero();
  for (Eigen::Index row = 0; row < m; row += gram_rows_per_update)
    gram.selfadjointView<Eigen::Lower>().rankUpdate(
        augmented.middleRows(row, std::min(gram_rows_per_update, m - row)).transpose());
  const Eigen::VectorXd scale = gram.diagonal().head(k).cwiseSqrt().cwiseInverse();  // D
  // D AᵀA D in place, its lower triangle (the upper one is zero and LLT reads the lower).
  auto normal = gram.topLeftCorner(k, k);
  normal = scale.asDiagonal() * normal * scale.asDiagonal();
  Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>, Eigen::Lower> cholesky(normal);
  if (cholesky.info() != Eigen::Success) return std::nullopt;
  const auto pivots = cholesky.matrixLLT().diagonal().cwiseAbs();
  if (pivots.minCoeff() < normal_equations_pivot_ratio * pivots.maxCoeff()) return std::nullopt;
  const auto system = augmented.leftCols(k);
  const auto data = augmented.rightCols(nodes);
  // y = D⁻¹x solves (D AᵀA D) y = D AᵀB; AᵀB is the Gram matrix's lower-left block.
  Eigen::MatrixXd unknowns = cholesky.solve(scale.asDiagonal() * gram.bottomLeftCorner(nodes, k).transpose());
  Eigen::MatrixXd residual = data;
  residual.noalias() -= system * (scale.asDiagonal() * unknowns);
  unknowns += cholesky.solve(scale.asDiagonal() * (system.transpose() * residual));
  coefficients = scale.asDiagonal() * unknowns;
  residual = data;
  residual.noalias() -= system * coefficients;
  return std::sqrt(residual.squaredNorm() / static_cast<double>(m * nodes));
}

}  // namespace

double solve_mfs_least_squares(Eigen::Ref<Eigen::MatrixXd> augmented, Eigen::Index unknowns,
                               const std::function<void()>& refill, Eigen::MatrixXd& coefficients) {
  const Eigen::Index m = augmented.rows(), k = unknowns, nodes = augmented.cols() - unknowns;
  const auto entries = static_cast<double>(m * nodes);
  if (const auto misfit = solve_by_normal_equations(augmented, k, coefficients)) return *misfit;
  // The systems the normal equations cannot take: Householder QR of [A | B] in place,
  // R = [R_AA R_AB; 0 R_BB], where R_AB is the top of Qᵀ·B (the coefficients solve R_AA x = R_AB) and R_BB carries the
  // norm of the rest (the misfit: the later reflectors act on rows ≥ k only, keeping their norms). Joint instead of QR
  // of A and then Qᵀ applied to B: ~12% less time on 850 × (250 + 22).
  Eigen::VectorXd householder(augmented.cols()), workspace(augmented.cols());
  Eigen::internal::householder_qr_inplace_blocked<Eigen::Ref<Eigen::MatrixXd>, Eigen::VectorXd>::run(
      augmented, householder, qr_block_columns, workspace.data());
  const auto diagonal = augmented.topLeftCorner(k, k).diagonal().cwiseAbs();
  if (diagonal.minCoeff() > 1e-12 * diagonal.maxCoeff()) {
    coefficients =
        augmented.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(augmented.topRightCorner(k, nodes));
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
