#pragma once
// The least-squares solve of the method of fundamental solutions (Martin et al. 2008
// §5, eq. (14)), shared by the 2D face coordinates and the 3D element basis: one
// factorisation of the m × k collocation system for all #nodes right-hand sides.
#include <Eigen/Core>
#include <functional>

namespace altfem::harmonic {

/// Solves min ‖A · coefficients − B‖ column by column, where `augmented` = [A | B]
/// holds the system A (its first k = `unknowns` columns, m ≥ k) and the data B (the
/// other #nodes columns). First by the normal equations (AᵀA column-equilibrated,
/// Cholesky, one step of iterative refinement: about half of QR's flops), kept when the
/// Cholesky pivots show κ(A) small enough for them to reach QR's accuracy; otherwise
/// `augmented` is overwritten by a blocked Householder QR of [A | B] in place (level-3,
/// several times faster than column pivoting): the reflectors of A's columns reach B in
/// the same trailing updates, so Qᵀ·B costs no pass of its own. When R's diagonal shows
/// A's columns (nearly) dependent, `refill` must write `augmented` again and the complete
/// orthogonal decomposition gives the minimum-norm solution (the pseudo-inverse, §5).
/// coefficients: k × #nodes. Returns the RMS misfit over all entries of B.
double solve_mfs_least_squares(Eigen::Ref<Eigen::MatrixXd> augmented, Eigen::Index unknowns,
                               const std::function<void()>& refill, Eigen::MatrixXd& coefficients);

}  // namespace altfem::harmonic
