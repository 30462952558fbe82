// The MFS least-squares solve (polyhedral/mfs_least_squares.hpp) on 3D MFS systems of
// a sphere: the normal-equation path where the system is well enough conditioned, QR
// where it is not, both against Eigen's column-pivoting QR, and linear data (the
// polynomial part: partition of unity, linear reproduction) fitted to round-off by both.
#include <gtest/gtest.h>

#include <Eigen/QR>
#include <cmath>
#include <numbers>

#include "polyhedral/mfs_least_squares.hpp"
#include "shared/common/eigen_decompositions.hpp"

namespace altfem::harmonic {
namespace {

// `count` nearly uniform points on the sphere of `radius` (Fibonacci lattice): #count × 3.
Eigen::MatrixX3d sphere_points(int count, double radius) {
  Eigen::MatrixX3d points(count, 3);
  const double golden = std::numbers::pi * (3 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i) {
    const double z = 1 - 2 * (i + 0.5) / count, r = std::sqrt(1 - z * z);
    points.row(i) << radius * r * std::cos(golden * i), radius * r * std::sin(golden * i), radius * z;
  }
  return points;
}

struct System {
  Eigen::MatrixXd augmented;  // [A | B]: m × (k + 3)
  Eigen::Index unknowns;      // k
};

// 600 collocation points on the unit sphere, 150 kernels 1/‖x − k_j‖ on the sphere of
// `centre_radius` and the linear polynomial; data: a harmonic function singular outside
// (1/‖x − (2, 0.5, 0)‖), a smooth non-harmonic one (x y² + z) and the linear x − 2y + 1.
System mfs_system(double centre_radius) {
  const Eigen::MatrixX3d points = sphere_points(600, 1), centres = sphere_points(150, centre_radius);
  const Eigen::Index m = points.rows(), c = centres.rows();
  System system{Eigen::MatrixXd(m, c + 4 + 3), c + 4};
  for (Eigen::Index i = 0; i < m; ++i) {
    const Eigen::RowVector3d x = points.row(i);
    for (Eigen::Index j = 0; j < c; ++j) system.augmented(i, j) = 1 / (x - centres.row(j)).norm();
    system.augmented.block(i, c, 1, 3) = x;
    system.augmented(i, c + 3) = 1;
    system.augmented(i, c + 4) = 1 / (x - Eigen::RowVector3d(2, 0.5, 0)).norm();
    system.augmented(i, c + 5) = x.x() * x.y() * x.y() + x.z();
    system.augmented(i, c + 6) = x.x() - 2 * x.y() + 1;
  }
  return system;
}

// Solves `system` and checks it against column-pivoting QR: the fitted values A·x agree
// (the coefficients of an ill-conditioned system need not), the returned misfit is the
// RMS of B − A·x, and linear data are fitted to round-off. Returns whether `augmented`
// was left as it was (the normal equations) or overwritten (QR).
bool solve_and_compare(const System& system) {
  const Eigen::Index k = system.unknowns;
  const Eigen::MatrixXd a = system.augmented.leftCols(k), b = system.augmented.rightCols(3);
  Eigen::MatrixXd augmented = system.augmented, coefficients;
  const double misfit = solve_mfs_least_squares(
      augmented, k, [&] { augmented = system.augmented; }, coefficients);
  const Eigen::MatrixXd reference = a * a.colPivHouseholderQr().solve(b), fitted = a * coefficients;
  EXPECT_LT((fitted - reference).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_NEAR(misfit, std::sqrt((b - fitted).squaredNorm() / static_cast<double>(b.size())), 1e-12);
  EXPECT_LT((fitted.col(2) - b.col(2)).cwiseAbs().maxCoeff(), 1e-11);  // linear data: exact
  return augmented == system.augmented;
}

// Centres at 1.5 radii (κ(A) = 4.3e5 after column scaling): the normal equations.
TEST(MfsLeastSquares, NormalEquationsOnAWellConditionedSystemMatchQr) {
  EXPECT_TRUE(solve_and_compare(mfs_system(1.5)));
}

// Centres at 2.5 radii (κ = 3.0e8): the normal equations, even refined, would miss both
// the fitted values and the linear data by more than the bounds (measured with the
// pivot guard switched off); the guard sends the system to QR.
TEST(MfsLeastSquares, IllConditionedSystemsGoToQr) { EXPECT_FALSE(solve_and_compare(mfs_system(2.5))); }

}  // namespace
}  // namespace altfem::harmonic
