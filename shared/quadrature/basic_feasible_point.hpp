#pragma once
// A basic feasible point of {x : A x = b, x >= 0} by the simplex method (COIN-OR Clp):
// a vertex of the feasible set, so at most rank(A) non-zeros (Longva et al. 2020,
// §4.4.2). There is no objective: Clp's phase 1 stops at the first feasible basis.
#include <Eigen/Core>
#include <optional>

namespace altfem {

/// A: #rows × #columns with full row rank (e.g. orthonormal rows, eq. (10)), b: #rows.
/// The solution (#columns, entries >= 0), or nullopt when Clp does not prove it feasible.
std::optional<Eigen::VectorXd> basic_feasible_point(const Eigen::Ref<const Eigen::MatrixXd>& A,
                                                    const Eigen::Ref<const Eigen::VectorXd>& b);

}  // namespace altfem
