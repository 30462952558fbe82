#include "shared/material/project_spd.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>

#include "shared/common/error.hpp"

namespace altfem {
namespace {

// One body for both sizes: Eigen's solver is templated on the matrix type, and
// the fixed 9 × 9 instance keeps everything on the stack.
template <typename MatrixType, typename Target>
void clamp_eigenvalues(Target&& symmetric, double minimum_eigenvalue) {
  if (!symmetric.allFinite()) {
    throw NumericalError("project_to_spd: the matrix has a non-finite entry");
  }
  const Eigen::SelfAdjointEigenSolver<MatrixType> eigen(symmetric);
  if (eigen.info() != Eigen::Success) {
    throw NumericalError("project_to_spd: the symmetric eigen-solver did not converge");
  }
  if (eigen.eigenvalues().minCoeff() >= minimum_eigenvalue) return;
  // A loop rather than cwiseMax: GCC 12 raises a false -Wmaybe-uninitialized
  // inside the AVX-512 max intrinsic that Eigen's vectorised cwiseMax uses.
  typename Eigen::SelfAdjointEigenSolver<MatrixType>::RealVectorType clamped = eigen.eigenvalues();
  for (double& value : clamped) value = std::max(value, minimum_eigenvalue);
  symmetric = eigen.eigenvectors() * clamped.asDiagonal() * eigen.eigenvectors().transpose();
}

}  // namespace

void project_to_spd(Eigen::Ref<Eigen::MatrixXd> symmetric, double minimum_eigenvalue) {
  clamp_eigenvalues<Eigen::MatrixXd>(symmetric, minimum_eigenvalue);
}

void project_to_spd(Matrix9d& symmetric, double minimum_eigenvalue) {
  clamp_eigenvalues<Matrix9d>(symmetric, minimum_eigenvalue);
}

}  // namespace altfem
