#include "shared/solve/petsc_coarse_level.hpp"

#ifdef ALTFEM_HAVE_PETSC
#include <Eigen/QR>
#include <algorithm>
#include <utility>

#include "shared/solve/petsc_session.hpp"
#include "shared/solve/process_ranks.hpp"

namespace altfem {

FirstOrderCoarseLevel::FirstOrderCoarseLevel(CoarseSpace space, const Eigen::MatrixXd& near_null_space)
    : space_(std::move(space)) {
  if (space_.empty() || near_null_space.cols() == 0) return;
  const auto coarse_dofs = static_cast<Eigen::Index>(3 * space_.fine_function.size());
  Eigen::MatrixXd restricted = space_.near_null_space;
  if (restricted.cols() == 0) {
    restricted.resize(coarse_dofs, near_null_space.cols());
    for (size_t function = 0; function < space_.fine_function.size(); ++function)
      restricted.middleRows(static_cast<Eigen::Index>(3 * function), 3) =
          near_null_space.middleRows(3 * space_.fine_function[function], 3);
  }
  // MatNullSpaceCreate wants orthonormal vectors; orthonormal over all coarse rows, so
  // over several ranks too, whichever rank holds which.
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(restricted);
  near_null_space_at_nodes_ = qr.householderQ() * Eigen::MatrixXd::Identity(coarse_dofs, restricted.cols());
}

FirstOrderCoarseLevel::~FirstOrderCoarseLevel() {
  if (!gentle_option_.empty()) PetscOptionsClearValue(nullptr, gentle_option_.c_str());
  MatDestroy(&interpolation_);
  MatDestroy(&coarse_);
}

PetscErrorCode FirstOrderCoarseLevel::configure(PC pc, bool aggressive_coarsening) {
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
  PetscCall(petsc::set_aggregation_threshold(coarse_pc));
  // Its coarsening as an option of this level, not PCGAMGSetAggressiveLevels: PETSc 3.18
  // resets the count whenever it reads the level's options, which PCMG does again at set-up.
  const char* prefix = nullptr;
  PetscCall(PCGetOptionsPrefix(coarse_pc, &prefix));
  if ((!aggressive_coarsening || space_.coarsen_gently) && !petsc::coarsening_chosen(prefix ? prefix : "")) {
    gentle_option_ = std::string("-") + (prefix ? prefix : "") + "pc_gamg_aggressive_coarsening";
    PetscCall(PetscOptionsSetValue(nullptr, gentle_option_.c_str(), "0"));
  }
  PetscCall(KSPSetFromOptions(coarse));
  PetscBool coarse_gamg = PETSC_FALSE;
  PetscCall(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(coarse_pc), PCGAMG, &coarse_gamg));
  if (!coarse_gamg && !gentle_option_.empty()) {  // the options chose another coarse solve, which never reads it
    PetscCall(PetscOptionsClearValue(nullptr, gentle_option_.c_str()));
    gentle_option_.clear();
  }
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

PetscErrorCode FirstOrderCoarseLevel::update(PC pc, Mat fine, const Eigen::SparseMatrix<double>& matrix,
                                             const Rows& rows) {
  if (!active_) return 0;
  // Over several ranks a DOF couples if any rank's share couples it.
  std::vector<double> couples(static_cast<size_t>(matrix.cols()), 0.0);
  for (Eigen::Index column = 0; column < matrix.outerSize(); ++column)
    for (Eigen::SparseMatrix<double>::InnerIterator entry(matrix, column); entry; ++entry)
      if (entry.row() != column && entry.value() != 0) {
        couples[column] = 1;
        break;
      }
  if (ranks::distributed()) ranks::sum(couples);
  std::vector<char> decoupled(couples.size());
  for (size_t dof = 0; dof < couples.size(); ++dof) decoupled[dof] = couples[dof] == 0;
  if (!interpolation_ || decoupled != decoupled_) {
    decoupled_ = std::move(decoupled);
    MatDestroy(&coarse_);
    PetscCall(build_interpolation(decoupled_, rows));
    PetscCall(PCMGSetInterpolation(pc, 1, interpolation_));
    // PCMG takes the restriction from the interpolation at its first set-up only: a later
    // interpolation (a released condition's DOFs coupled again) needs its own set.
    PetscCall(PCMGSetRestriction(pc, 1, interpolation_));
  }
  // Pᵀ A P's pattern is computed again for another fine matrix (a new pattern), its values
  // only for new values of the same one.
  PetscObjectId fine_id;
  PetscCall(PetscObjectGetId(reinterpret_cast<PetscObject>(fine), &fine_id));
  if (coarse_ && fine_id == fine_id_) {
    PetscCall(MatPtAP(fine, interpolation_, MAT_REUSE_MATRIX, PETSC_DEFAULT, &coarse_));
  } else {
    MatDestroy(&coarse_);
    fine_id_ = fine_id;
    PetscCall(MatPtAP(fine, interpolation_, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &coarse_));
    PetscCall(MatSetBlockSize(coarse_, 3));
    PetscCall(set_coarse_near_null_space());
  }
  KSP coarse;
  PetscCall(PCMGGetCoarseSolve(pc, &coarse));
  PetscCall(KSPSetOperators(coarse, coarse_, coarse_));
  return 0;
}

PetscErrorCode FirstOrderCoarseLevel::build_interpolation(const std::vector<char>& decoupled, const Rows& rows) {
  MatDestroy(&interpolation_);
  const auto fine_dofs = static_cast<PetscInt>(decoupled.size());
  const auto petsc_row = [&](Eigen::Index dof) {
    return rows.petsc_of_method.empty() ? static_cast<PetscInt>(dof) : rows.petsc_of_method[dof];
  };
  // Every rank's first fine row, then each coarse function's rank (its node's) and rows,
  // numbered rank by rank in the coarse functions' order.
  PetscMPIInt rank_count = 1, rank = 0;
  PetscCallMPI(MPI_Comm_size(rows.communicator, &rank_count));
  PetscCallMPI(MPI_Comm_rank(rows.communicator, &rank));
  std::vector<PetscInt> fine_starts(static_cast<size_t>(rank_count) + 1, 0);
  PetscCallMPI(MPI_Allgather(&rows.last_row, 1, MPIU_INT, fine_starts.data() + 1, 1, MPIU_INT, rows.communicator));
  const size_t coarse_count = space_.fine_function.size();
  std::vector<int> owner(coarse_count);
  std::vector<PetscInt> coarse_starts(static_cast<size_t>(rank_count) + 1, 0);
  for (size_t function = 0; function < coarse_count; ++function) {
    const PetscInt row = petsc_row(3 * static_cast<Eigen::Index>(space_.fine_function[function]));
    owner[function] =
        static_cast<int>(std::upper_bound(fine_starts.begin() + 1, fine_starts.end(), row) - (fine_starts.begin() + 1));
    ++coarse_starts[owner[function] + 1];
  }
  for (PetscMPIInt r = 0; r < rank_count; ++r) coarse_starts[r + 1] += coarse_starts[r];
  coarse_row_.resize(coarse_count);
  std::vector<PetscInt> next(coarse_starts.begin(), coarse_starts.end() - 1);
  for (size_t function = 0; function < coarse_count; ++function) coarse_row_[function] = 3 * next[owner[function]]++;
  first_coarse_row_ = 3 * coarse_starts[rank];
  last_coarse_row_ = 3 * coarse_starts[rank + 1];
  const PetscInt coarse_dofs = 3 * coarse_starts[rank_count];

  // This rank's fine rows: the DOF of each.
  const PetscInt local_rows = rows.last_row - rows.first_row;
  std::vector<Eigen::Index> dof_of_row(static_cast<size_t>(local_rows));
  for (Eigen::Index dof = 0; dof < fine_dofs; ++dof)
    if (const PetscInt row = petsc_row(dof); row >= rows.first_row && row < rows.last_row)
      dof_of_row[row - rows.first_row] = dof;
  const Eigen::SparseMatrix<double, Eigen::RowMajor> functions = space_.prolongation;
  std::vector<PetscInt> starts(static_cast<size_t>(local_rows) + 1, 0), columns;
  std::vector<PetscScalar> values;
  std::vector<std::pair<PetscInt, PetscScalar>> row_entries;
  for (PetscInt local = 0; local < local_rows; ++local) {
    const Eigen::Index dof = dof_of_row[local];
    const auto function = static_cast<int>(dof / 3), component = static_cast<int>(dof % 3);
    row_entries.clear();
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator entry(functions, function); entry; ++entry) {
      const auto coarse = static_cast<size_t>(entry.col());
      const Eigen::Index node_dof = 3 * static_cast<Eigen::Index>(space_.fine_function[coarse]) + component;
      // A decoupled DOF keeps only the coarse function at its own node, which then
      // holds nothing else: the coarse level neither moves it nor couples through it.
      if (node_dof != dof && (decoupled[dof] || decoupled[node_dof])) continue;
      row_entries.emplace_back(coarse_row_[coarse] + component, entry.value());
    }
    std::sort(row_entries.begin(), row_entries.end());  // AIJ wants each row's columns in order
    for (const auto& [column, value] : row_entries) {
      columns.push_back(column);
      values.push_back(value);
    }
    starts[local + 1] = static_cast<PetscInt>(columns.size());
  }
  PetscCall(MatCreate(rows.communicator, &interpolation_));
  PetscCall(
      MatSetSizes(interpolation_, local_rows, last_coarse_row_ - first_coarse_row_, PETSC_DETERMINE, coarse_dofs));
  PetscCall(MatSetType(interpolation_, rank_count > 1 ? MATMPIAIJ : MATSEQAIJ));
  PetscCall(MatSetBlockSizes(interpolation_, 3, 3));
  if (rank_count > 1)
    PetscCall(MatMPIAIJSetPreallocationCSR(interpolation_, starts.data(), columns.data(), values.data()));
  else PetscCall(MatSeqAIJSetPreallocationCSR(interpolation_, starts.data(), columns.data(), values.data()));
  return 0;
}

PetscErrorCode FirstOrderCoarseLevel::set_coarse_near_null_space() {
  if (near_null_space_at_nodes_.cols() == 0) return 0;
  std::vector<Vec> vectors(static_cast<size_t>(near_null_space_at_nodes_.cols()));
  for (Eigen::Index mode = 0; mode < near_null_space_at_nodes_.cols(); ++mode) {
    PetscCall(MatCreateVecs(coarse_, &vectors[mode], nullptr));
    PetscScalar* values;
    PetscCall(VecGetArray(vectors[mode], &values));
    for (size_t function = 0; function < coarse_row_.size(); ++function) {
      const PetscInt row = coarse_row_[function];
      if (row < first_coarse_row_ || row >= last_coarse_row_) continue;
      for (Eigen::Index component = 0; component < 3; ++component)
        values[row - first_coarse_row_ + component] =
            near_null_space_at_nodes_(3 * static_cast<Eigen::Index>(function) + component, mode);
    }
    PetscCall(VecRestoreArray(vectors[mode], &values));
  }
  MPI_Comm communicator;
  PetscCall(PetscObjectGetComm(reinterpret_cast<PetscObject>(coarse_), &communicator));
  MatNullSpace space;
  PetscCall(
      MatNullSpaceCreate(communicator, PETSC_FALSE, static_cast<PetscInt>(vectors.size()), vectors.data(), &space));
  PetscCall(MatSetNearNullSpace(coarse_, space));
  PetscCall(MatNullSpaceDestroy(&space));
  for (Vec& vector : vectors) PetscCall(VecDestroy(&vector));
  return 0;
}

}  // namespace altfem
#endif
