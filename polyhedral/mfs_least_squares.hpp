#pragma once
// The least-squares solve of the method of fundamental solutions (Martin et al. 2008
// §5, eq. (14)), shared by the 2D face coordinates and the 3D element basis: one
// factorisation of the m × k collocation system for all #nodes right-hand sides.
#include <Eigen/Core>
#include <functional>

namespace altfem::harmonic {

/// Solves min ‖system · coefficients − data‖ column by column. `system` (m × k, m ≥ k)
/// and `data` (m × #nodes) are overwritten. Blocked Householder QR in place (level-3,
/// several times faster than column pivoting); when R's diagonal shows the columns
/// (nearly) dependent, `refill` must write system and data again and the complete
/// orthogonal decomposition gives the minimum-norm solution (the pseudo-inverse, §5).
/// coefficients: k × #nodes. Returns the RMS misfit over all entries of data.
double solve_mfs_least_squares(Eigen::Ref<Eigen::MatrixXd> system, Eigen::Ref<Eigen::MatrixXd> data,
                               const std::function<void()>& refill, Eigen::MatrixXd& coefficients);

}  // namespace altfem::harmonic
