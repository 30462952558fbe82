#include "shared/quadrature/caratheodory_recombination.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>
#include <vector>

#include "shared/common/eigen_decompositions.hpp"

namespace altfem {
namespace {

/// Pivots below this fraction of the largest count as dependent directions.
constexpr double rank_threshold = 1e-14;
/// The elimination route's least ratio of its smallest pivot to its largest: B's null
/// vectors are then accurate to about 1e-16 / 1e-8, ample for choosing points.
constexpr double minimum_pivot_ratio = 1e-8;

/// The largest step t with λ − t v >= 0 and the first index that reaches zero, over the
/// λ_i > 0; pivot −1 when v has no positive entry there. The ratios are formed for all
/// entries at once and the first least one taken: a branch per entry, on the signs of v,
/// mispredicted half the time, had been most of the elimination's cost (`perf`).
std::pair<Eigen::Index, double> ratio_test(const Eigen::Ref<const Eigen::VectorXd>& v, const Eigen::VectorXd& lambda,
                                           Eigen::ArrayXd& ratios) {
  const double infinity = std::numeric_limits<double>::infinity();
  ratios = (v.array() > 0.0 && lambda.array() > 0.0).select(lambda.array() / v.array(), infinity);
  Eigen::Index pivot = -1;
  double step = infinity;
  for (Eigen::Index i = 0; i < ratios.size(); ++i)
    if (ratios(i) < step) {
      step = ratios(i);
      pivot = i;
    }
  return {pivot, pivot < 0 ? 0.0 : step};
}

/// A basis of null(C) (n columns, C: r × n) by a pivoted QR, which also reveals the rank:
/// C Π = Q [R₁ R₂] with R₁ (rank × rank) upper triangular, null(C) = Π [−R₁⁻¹ R₂; I]; an
/// empty matrix when C has full column rank.
Eigen::MatrixXd null_space_by_qr(const Eigen::Ref<const Eigen::MatrixXd>& C) {
  const Eigen::Index n = C.cols();
  Eigen::MatrixXd null_space;
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(C);
  qr.setThreshold(rank_threshold);
  const Eigen::Index rank = qr.rank();
  if (rank >= n) return null_space;
  const Eigen::MatrixXd& R = qr.matrixQR();
  Eigen::MatrixXd permuted(n, n - rank);
  permuted.topRows(rank) = -R.topRightCorner(rank, n - rank);
  R.topLeftCorner(rank, rank).triangularView<Eigen::Upper>().solveInPlace(permuted.topRows(rank));
  permuted.bottomRows(n - rank).setIdentity();
  null_space = qr.colsPermutation() * permuted;
  return null_space;
}

/// A basis of null(C) (n columns, C: r × n), or an empty matrix when C has full column
/// rank. First by Gauss–Jordan elimination with partial pivoting on C's first r columns B,
/// applied to all of C, when its pivots say B is well conditioned: C becomes [I B⁻¹N] with
/// C = [B N], and null(C) = [−B⁻¹ N; I]. One pass over the rows of a row-major copy: at
/// r = 35, n = 70 (fcm Hex20's stiffness rules) cheaper than Eigen's LU and two
/// triangular solves, whose blocking does not pay at these sizes (`bench_quadrature
/// --method caratheodory --part cell`: recombination 0.244 → 0.182 ms with the ratio
/// test below, docs/performance.md). Otherwise by
/// the pivoted QR. Either basis need only be accurate enough to choose the points:
/// simplify_quadrature re-solves the weights on them exactly.
Eigen::MatrixXd null_space_of(const Eigen::Ref<const Eigen::MatrixXd>& C,
                              Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>& A) {
  const Eigen::Index r = C.rows(), n = C.cols();
  if (n <= r) return null_space_by_qr(C);
  A = C;
  double largest = 0.0, smallest = std::numeric_limits<double>::infinity();
  for (Eigen::Index j = 0; j < r; ++j) {
    Eigen::Index row = 0;
    A.col(j).tail(r - j).cwiseAbs().maxCoeff(&row);
    row += j;
    const double pivot = A(row, j);
    largest = std::max(largest, std::abs(pivot));
    smallest = std::min(smallest, std::abs(pivot));
    if (!(smallest > minimum_pivot_ratio * largest)) return null_space_by_qr(C);
    if (row != j) A.row(row).swap(A.row(j));
    A.row(j).tail(n - j) /= pivot;
    for (Eigen::Index i = 0; i < r; ++i) {
      const double factor = A(i, j);
      if (i != j && factor != 0.0) A.row(i).tail(n - j) -= factor * A.row(j).tail(n - j);
    }
  }
  Eigen::MatrixXd null_space(n, n - r);
  null_space.topRows(r) = -A.rightCols(n - r);
  null_space.bottomRows(n - r).setIdentity();
  return null_space;
}

/// What eliminate() reuses from one group matrix to the next.
struct EliminationScratch {
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> reduced;  ///< C reduced (null_space_of)
  Eigen::ArrayXd ratios;                                                           ///< ratio_test's
};

/// Carathéodory–Steinitz elimination on the columns C (r × n) with weights λ > 0 (in
/// place): along each null vector v of C (C v = 0, so C λ is unchanged), step until
/// the first weight reaches zero and drop that column; the remaining null vectors are
/// made zero there first, so later steps never revive it. Leaves at most rank(C)
/// non-zeros. The null space is computed once (null_space_of).
void eliminate(const Eigen::Ref<const Eigen::MatrixXd>& C, Eigen::VectorXd& lambda, EliminationScratch& scratch) {
  const Eigen::Index n = C.cols();
  Eigen::MatrixXd null_space = null_space_of(C, scratch.reduced);
  for (Eigen::Index k = 0; k < null_space.cols(); ++k) {
    Eigen::Ref<Eigen::VectorXd> v = null_space.col(k);
    // Either direction keeps C λ: v, or −v when v has no positive entry on the remaining weights.
    auto [pivot, step] = ratio_test(v, lambda, scratch.ratios);
    if (pivot < 0) {
      v = -v;
      std::tie(pivot, step) = ratio_test(v, lambda, scratch.ratios);
    }
    if (pivot < 0) continue;  // v vanishes on the remaining weights
    lambda -= step * v;
    lambda(pivot) = 0.0;
    for (Eigen::Index i = 0; i < n; ++i) lambda(i) = std::max(lambda(i), 0.0);
    for (Eigen::Index later = k + 1; later < null_space.cols(); ++later) {
      null_space.col(later) -= (null_space(pivot, later) / v(pivot)) * v;
      null_space(pivot, later) = 0.0;
    }
  }
}

}  // namespace

Eigen::VectorXd caratheodory_recombination(const Eigen::Ref<const Eigen::MatrixXd>& columns,
                                           const Eigen::Ref<const Eigen::VectorXd>& weights, Eigen::Index target_size) {
  const Eigen::Index rows = columns.rows();
  Eigen::VectorXd result = weights;
  std::vector<Eigen::Index> active;
  for (Eigen::Index j = 0; j < weights.size(); ++j) {
    if (weights(j) > 0.0) active.push_back(j);
  }
  const Eigen::Index group_count = 2 * std::max<Eigen::Index>(rows, 1);
  Eigen::MatrixXd group_sums(rows, group_count);
  Eigen::VectorXd group_weights(group_count);
  std::vector<Eigen::Index> kept;
  EliminationScratch scratch;
  while (static_cast<Eigen::Index>(active.size()) > target_size) {
    // Consecutive groups of (nearly) equal size; a group's column is Σ w_j a_j.
    const Eigen::Index n = static_cast<Eigen::Index>(active.size());
    const Eigen::Index groups = std::min(group_count, n);
    const auto begin = [&](Eigen::Index g) { return g * n / groups; };
    group_sums.setZero();
    for (Eigen::Index g = 0; g < groups; ++g) {
      for (Eigen::Index i = begin(g); i < begin(g + 1); ++i)
        group_sums.col(g) += result(active[i]) * columns.col(active[i]);
    }
    group_weights.resize(groups);
    group_weights.setOnes();
    eliminate(group_sums.leftCols(groups), group_weights, scratch);
    kept.clear();
    for (Eigen::Index g = 0; g < groups; ++g) {
      for (Eigen::Index i = begin(g); i < begin(g + 1); ++i) {
        if (group_weights(g) > 0.0) {
          result(active[i]) *= group_weights(g);
          kept.push_back(active[i]);
        } else {
          result(active[i]) = 0.0;
        }
      }
    }
    if (kept.size() == active.size()) break;  // independent group sums: nothing to eliminate
    active.swap(kept);
  }
  return result;
}

}  // namespace altfem
