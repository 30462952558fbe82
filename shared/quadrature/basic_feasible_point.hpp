#pragma once
// Points of {x : A x = b, x >= 0} by the simplex method (COIN-OR Clp): a basic one, a
// vertex of the feasible set, so at most rank(A) non-zeros (Longva et al. 2020, §4.4.2),
// or one spread over every column.
#include <Eigen/Core>
#include <optional>

namespace altfem {

/// A: #rows × #columns with full row rank (e.g. orthonormal rows, eq. (10)), b: #rows.
/// The solution (#columns, entries >= 0), or nullopt when Clp does not prove it feasible.
std::optional<Eigen::VectorXd> basic_feasible_point(const Eigen::Ref<const Eigen::MatrixXd>& A,
                                                    const Eigen::Ref<const Eigen::VectorXd>& b);

/// A point of {x : A x = b, x >= 0} with every entry positive where it can be: x = t·prior
/// + s, s >= 0, with the largest t (one LP in the columns of A and A·prior, Clp). A basic
/// feasible point keeps at most rank(A) non-zeros; this one keeps every column whose
/// prior is positive, at least t times its prior, and is corrected to meet A x = b to
/// round-off. prior: #columns, entries > 0. Nullopt when Clp does not prove the LP optimal,
/// t is 0 (no point is strictly inside) or the correction makes an entry non-positive.
std::optional<Eigen::VectorXd> spread_feasible_point(const Eigen::Ref<const Eigen::MatrixXd>& A,
                                                     const Eigen::Ref<const Eigen::VectorXd>& b,
                                                     const Eigen::Ref<const Eigen::VectorXd>& prior);

}  // namespace altfem
