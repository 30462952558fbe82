#include "shared/solve/petsc_coarse_level.hpp"

#ifdef ALTFEM_HAVE_PETSC
#include <Eigen/QR>
#include <utility>

namespace altfem {

FirstOrderCoarseLevel::FirstOrderCoarseLevel(CoarseSpace space, const Eigen::MatrixXd& near_null_space)
    : space_(std::move(space)) {
  if (space_.empty() || near_null_space.cols() == 0) return;
  const auto coarse_dofs = static_cast<Eigen::Index>(3 * space_.fine_function.size());
  Eigen::MatrixXd restricted(coarse_dofs, near_null_space.cols());
  for (size_t function = 0; function < space_.fine_function.size(); ++function)
    restricted.middleRows(static_cast<Eigen::Index>(3 * function), 3) =
        near_null_space.middleRows(3 * space_.fine_function[function], 3);
  // MatNullSpaceCreate wants orthonormal vectors.
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(restricted);
  coarse_near_null_space_ = qr.householderQ() * Eigen::MatrixXd::Identity(coarse_dofs, restricted.cols());
}

FirstOrderCoarseLevel::~FirstOrderCoarseLevel() {
  MatDestroy(&interpolation_);
  MatDestroy(&coarse_);
}

PetscErrorCode FirstOrderCoarseLevel::configure(PC pc) {
  if (space_.empty()) return 0;
  PetscBool gamg = PETSC_FALSE;
  PetscCall(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(pc), PCGAMG, &gamg));
  if (!gamg) return 0;
  PetscCall(PCSetType(pc, PCMG));
  PetscCall(PCMGSetLevels(pc, 2, nullptr));
  PetscCall(PCMGSetGalerkin(pc, PC_MG_GALERKIN_NONE));  // Pᵀ A P made here, with its near-null space
  KSP coarse;
  PetscCall(PCMGGetCoarseSolve(pc, &coarse));
  PetscCall(KSPSetType(coarse, KSPPREONLY));
  PC coarse_pc;
  PetscCall(KSPGetPC(coarse, &coarse_pc));
  PetscCall(PCSetType(coarse_pc, PCGAMG));
  // Aggregation drops graph edges weaker than 0.05 (PETSc's manual: 0.01-0.05 for
  // elasticity; its default, 0, keeps them all): the cantilever's Hex20 20 × 2 × 2 took
  // 32 iterations with 0, 29 with 0.05, and Tet10 40 × 4 × 4 33 against 30.
  PetscReal threshold = 0.05;
  PetscCall(PCGAMGSetThreshold(coarse_pc, &threshold, 1));
  PetscCall(KSPSetFromOptions(coarse));
  KSP fine;
  PetscCall(PCMGGetSmoother(pc, 1, &fine));
  // Chebyshev on the diagonal, as GAMG's levels: PCMG's default, symmetric SOR, took as
  // many iterations, each dearer, and with fcm's Additive Schwarz as the smoother
  // (petsc_finest_smoother.hpp) CG broke down on an indefinite preconditioner.
  PC fine_pc;
  PetscCall(KSPGetPC(fine, &fine_pc));
  PetscCall(PCSetType(fine_pc, PCJACOBI));
  PetscCall(KSPSetFromOptions(fine));
  active_ = true;
  return 0;
}

PetscErrorCode FirstOrderCoarseLevel::update(PC pc, Mat fine, const Eigen::SparseMatrix<double>& matrix) {
  if (!active_) return 0;
  std::vector<char> decoupled(static_cast<size_t>(matrix.cols()), 1);
  for (Eigen::Index column = 0; column < matrix.outerSize(); ++column)
    for (Eigen::SparseMatrix<double>::InnerIterator entry(matrix, column); entry; ++entry)
      if (entry.row() != column && entry.value() != 0) {
        decoupled[column] = 0;
        break;
      }
  if (!interpolation_ || decoupled != decoupled_) {
    decoupled_ = std::move(decoupled);
    MatDestroy(&coarse_);
    PetscCall(build_interpolation(decoupled_, static_cast<PetscInt>(matrix.rows())));
    PetscCall(PCMGSetInterpolation(pc, 1, interpolation_));
    PetscCall(MatPtAP(fine, interpolation_, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &coarse_));
    PetscCall(MatSetBlockSize(coarse_, 3));
    PetscCall(set_coarse_near_null_space());
  } else {
    PetscCall(MatPtAP(fine, interpolation_, MAT_REUSE_MATRIX, PETSC_DEFAULT, &coarse_));
  }
  KSP coarse;
  PetscCall(PCMGGetCoarseSolve(pc, &coarse));
  PetscCall(KSPSetOperators(coarse, coarse_, coarse_));
  return 0;
}

PetscErrorCode FirstOrderCoarseLevel::build_interpolation(const std::vector<char>& decoupled, PetscInt fine_dofs) {
  MatDestroy(&interpolation_);
  const Eigen::SparseMatrix<double, Eigen::RowMajor> rows = space_.prolongation;
  const auto coarse_dofs = static_cast<PetscInt>(3 * space_.fine_function.size());
  std::vector<PetscInt> starts(static_cast<size_t>(fine_dofs) + 1, 0), columns;
  std::vector<PetscScalar> values;
  columns.reserve(static_cast<size_t>(3 * rows.nonZeros()));
  values.reserve(static_cast<size_t>(3 * rows.nonZeros()));
  for (PetscInt dof = 0; dof < fine_dofs; ++dof) {
    const int function = static_cast<int>(dof / 3), component = static_cast<int>(dof % 3);
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator entry(rows, function); entry; ++entry) {
      const auto coarse = static_cast<int>(entry.col());
      const int node_dof = 3 * space_.fine_function[coarse] + component;
      // A decoupled DOF keeps only the coarse function at its own node, which then
      // holds nothing else: the coarse level neither moves it nor couples through it.
      const bool own_node = node_dof == dof;
      if (!own_node && (decoupled[dof] || decoupled[node_dof])) continue;
      columns.push_back(3 * coarse + component);
      values.push_back(entry.value());
    }
    starts[dof + 1] = static_cast<PetscInt>(columns.size());
  }
  PetscCall(MatCreate(PETSC_COMM_SELF, &interpolation_));
  PetscCall(MatSetSizes(interpolation_, fine_dofs, coarse_dofs, fine_dofs, coarse_dofs));
  PetscCall(MatSetType(interpolation_, MATSEQAIJ));
  PetscCall(MatSetBlockSizes(interpolation_, 3, 3));
  PetscCall(MatSeqAIJSetPreallocationCSR(interpolation_, starts.data(), columns.data(), values.data()));
  return 0;
}

PetscErrorCode FirstOrderCoarseLevel::set_coarse_near_null_space() {
  if (coarse_near_null_space_.cols() == 0) return 0;
  std::vector<Vec> vectors(static_cast<size_t>(coarse_near_null_space_.cols()));
  for (Eigen::Index mode = 0; mode < coarse_near_null_space_.cols(); ++mode) {
    PetscCall(MatCreateVecs(coarse_, &vectors[mode], nullptr));
    PetscScalar* values;
    PetscCall(VecGetArray(vectors[mode], &values));
    for (Eigen::Index row = 0; row < coarse_near_null_space_.rows(); ++row)
      values[row] = coarse_near_null_space_(row, mode);
    PetscCall(VecRestoreArray(vectors[mode], &values));
  }
  MatNullSpace space;
  PetscCall(
      MatNullSpaceCreate(PETSC_COMM_SELF, PETSC_FALSE, static_cast<PetscInt>(vectors.size()), vectors.data(), &space));
  PetscCall(MatSetNearNullSpace(coarse_, space));
  PetscCall(MatNullSpaceDestroy(&space));
  for (Vec& vector : vectors) PetscCall(VecDestroy(&vector));
  return 0;
}

}  // namespace altfem
#endif
