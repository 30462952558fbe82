#include "shared/solve/petsc_solver.hpp"

#include "shared/common/eigen_decompositions.hpp"
#include "shared/common/error.hpp"
#include "shared/solve/partitioned_rows.hpp"
#include "shared/solve/petsc_coarse_level.hpp"
#include "shared/solve/petsc_finest_smoother.hpp"
#include "shared/solve/petsc_session.hpp"
#include "shared/solve/process_ranks.hpp"

#ifdef ALTFEM_HAVE_PETSC

#include <petscksp.h>

#include <Eigen/QR>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace altfem {
namespace {

using petsc::check;

class PetscSolver final : public LinearSolver {
public:
  explicit PetscSolver(const LinearSolverOptions& options)
      : prefix_(petsc::next_prefix()), coarse_level_(options.coarse_space, options.near_null_space) {
    petsc::start();
    if (options.near_null_space.cols() > 0) {
      // MatNullSpaceCreate wants orthonormal vectors.
      const Eigen::HouseholderQR<Eigen::MatrixXd> qr(options.near_null_space);
      near_null_space_ =
          qr.householderQ() * Eigen::MatrixXd::Identity(options.near_null_space.rows(), options.near_null_space.cols());
    }
    // PETSC_COMM_WORLD is MPI's world only once PETSc has started.
    if (ranks::distributed()) {
      communicator_ = PETSC_COMM_WORLD;
      share_row_owners_ = options.share_row_owners;
    }
    if (options.method_smoother)
      finest_smoother_ = FinestLevelSmoother(options.custom_preconditioner, ranks::distributed());
    check(KSPCreate(communicator_, &ksp_), "KSPCreate");
    check(KSPSetOptionsPrefix(ksp_, prefix_.c_str()), "KSPSetOptionsPrefix");
    check(KSPSetType(ksp_, KSPCG), "KSPSetType");
    PC preconditioner;
    check(KSPGetPC(ksp_, &preconditioner), "KSPGetPC");
    check(PCSetType(preconditioner, PCGAMG), "PCSetType");
    check(petsc::set_aggregation_threshold(preconditioner), "PCGAMGSetThreshold");
    check(KSPSetTolerances(ksp_, options.tolerance, 0.0, PETSC_DEFAULT, options.max_iterations), "KSPSetTolerances");
    const std::string inserted = petsc::prefixed_options(options.petsc_options, prefix_, option_names_);
    const PetscErrorCode inserting = PetscOptionsInsertString(nullptr, inserted.c_str());
    const PetscErrorCode reading = inserting ? inserting : KSPSetFromOptions(ksp_);
    if (reading)
      throw InputError("solver.petsc_options: \"" + options.petsc_options + "\": " + petsc::error_text(reading));
    // CG stops by altfem's criterion for every iterative solver, ‖b − A x‖ ≤ tolerance ‖b‖,
    // unless the options say otherwise; a method that cannot measure that norm with its
    // preconditioner's side (GMRES preconditioned on the left) keeps PETSc's default.
    KSPType method;
    check(KSPGetType(ksp_, &method), "KSPGetType");
    const bool norm_chosen = options.petsc_options.find("-ksp_norm_type") != std::string::npos;
    if (!norm_chosen && std::string(method) == KSPCG)
      check(KSPSetNormType(ksp_, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
    // GAMG without aggressive coarsening where one set-up serves several solves, unless the
    // options choose: set after they are read, since PETSc 3.18 resets the level count when
    // it reads them (the first-order level's GAMG likewise, petsc_coarse_level.hpp).
    PetscBool gamg = PETSC_FALSE;
    check(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(preconditioner), PCGAMG, &gamg),
          "PetscObjectTypeCompare");
    if (gamg && !options.aggressive_coarsening && !petsc::coarsening_chosen(prefix_))
      check(PCGAMGSetAggressiveLevels(preconditioner, 0), "PCGAMGSetAggressiveLevels");
    check(coarse_level_.configure(preconditioner, options.aggressive_coarsening), "the first-order coarse level");
    check(finest_smoother_.configure(preconditioner, options.petsc_options), "the finest level's smoother");
  }

  ~PetscSolver() override {
    for (const std::string& name : option_names_) PetscOptionsClearValue(nullptr, ("-" + name).c_str());
    KSPDestroy(&ksp_);
    destroy_arrays();
  }

  std::string_view name() const override { return "petsc"; }

protected:
  // PETSc's AIJ is compressed rows, Eigen's matrix compressed columns: the rows of A are
  // the columns of Aᵀ, so the pattern is transposed once here and each later
  // factorisation gathers its values through csr_from_csc_. PETSc works on these arrays
  // themselves (MatCreateSeqAIJWithArrays), without a second copy of the matrix.
  void analyze_pattern(const Eigen::SparseMatrix<double>& matrix) override {
    // The KSP may still hold the old matrix, which reads the arrays rebuilt below; it is
    // replaced before anything reads it again (factorize_values).
    destroy_arrays();
    if (!share_row_owners_.empty()) return analyze_shares(matrix);
    const auto size = static_cast<PetscInt>(matrix.rows());
    // Three DOFs per basis function: GAMG aggregates whole functions, as elasticity needs.
    const PetscInt block = size % 3 == 0 ? 3 : 1;
    number_rows(matrix, block);
    const PetscInt rows = last_row_ - first_row_;
    row_starts_.assign(rows + 1, 0);
    // This rank's row of DOF `dof` (in PETSc's numbering, less first_row_), or −1.
    const auto local_row = [&](Eigen::Index dof) -> PetscInt {
      const PetscInt row = petsc_index(dof);
      return row >= first_row_ && row < last_row_ ? row - first_row_ : -1;
    };
    for (Eigen::Index column = 0; column < matrix.outerSize(); ++column)
      for (Eigen::SparseMatrix<double>::InnerIterator entry(matrix, column); entry; ++entry)
        if (const PetscInt row = local_row(entry.row()); row >= 0) ++row_starts_[row + 1];
    for (PetscInt row = 0; row < rows; ++row) row_starts_[row + 1] += row_starts_[row];
    columns_.resize(row_starts_[rows]);
    csr_from_csc_.resize(row_starts_[rows]);
    std::vector<PetscInt> next(row_starts_.begin(), row_starts_.end() - 1);
    // Columns in increasing order (PETSc's), so every row's column indices come out
    // sorted, as AIJ needs.
    for (const Eigen::Index column : columns_in_petsc_order(size))
      for (Eigen::SparseMatrix<double>::InnerIterator entry(matrix, column); entry; ++entry) {
        const PetscInt row = local_row(entry.row());
        if (row < 0) continue;
        const PetscInt position = next[row]++;
        columns_[position] = petsc_index(column);
        csr_from_csc_[position] = static_cast<int>(&entry.value() - matrix.valuePtr());
      }

    values_.assign(columns_.size(), 0.0);
    if (ranks::distributed()) {
      // MATMPIAIJ keeps its own copy (diagonal and off-diagonal blocks): values are
      // refreshed row by row (factorize_values).
      check(MatCreate(communicator_, &matrix_), "MatCreate");
      check(MatSetSizes(matrix_, rows, rows, size, size), "MatSetSizes");
      check(MatSetType(matrix_, MATMPIAIJ), "MatSetType");
      check(MatSetBlockSize(matrix_, block), "MatSetBlockSize");
      check(MatMPIAIJSetPreallocationCSR(matrix_, row_starts_.data(), columns_.data(), values_.data()),
            "MatMPIAIJSetPreallocationCSR");
      create_vectors(size);
    } else {
      check(MatCreateSeqAIJWithArrays(PETSC_COMM_SELF, size, size, row_starts_.data(), columns_.data(), values_.data(),
                                      &matrix_),
            "MatCreateSeqAIJWithArrays");
      if (block == 3) check(MatSetBlockSize(matrix_, 3), "MatSetBlockSize");
      create_vectors(size);
    }
  }

  void factorize_values(const Eigen::SparseMatrix<double>& matrix) override {
    const double* source = matrix.valuePtr();
    if (!share_row_owners_.empty()) {
      // Each rank adds its share; PETSc sends the rows another rank owns to it.
      check(MatZeroEntries(matrix_), "MatZeroEntries");
      for_each_row_of_share(matrix, [&](PetscInt row, PetscInt count, const PetscInt* columns, const double* values) {
        check(MatSetValues(matrix_, 1, &row, count, columns, values, ADD_VALUES), "MatSetValues");
      });
      check(MatAssemblyBegin(matrix_, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
      check(MatAssemblyEnd(matrix_, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
    } else if (ranks::distributed()) {
      for (std::size_t position = 0; position < csr_from_csc_.size(); ++position)
        values_[position] = source[csr_from_csc_[position]];
      for (PetscInt row = 0; row + first_row_ < last_row_; ++row) {
        const PetscInt global_row = first_row_ + row;
        check(MatSetValues(matrix_, 1, &global_row, row_starts_[row + 1] - row_starts_[row],
                           columns_.data() + row_starts_[row], values_.data() + row_starts_[row], INSERT_VALUES),
              "MatSetValues");
      }
      check(MatAssemblyBegin(matrix_, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
      check(MatAssemblyEnd(matrix_, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
    } else {
      PetscScalar* values;
      check(MatSeqAIJGetArray(matrix_, &values), "MatSeqAIJGetArray");
      for (std::size_t position = 0; position < csr_from_csc_.size(); ++position)
        values[position] = source[csr_from_csc_[position]];
      check(MatSeqAIJRestoreArray(matrix_, &values), "MatSeqAIJRestoreArray");
    }
    check(KSPSetOperators(ksp_, matrix_, matrix_), "KSPSetOperators");
    PC preconditioner;
    check(KSPGetPC(ksp_, &preconditioner), "KSPGetPC");
    check(
        coarse_level_.update(preconditioner, matrix_, matrix, {petsc_of_method_, first_row_, last_row_, communicator_}),
        "the first-order coarse level");
    check(KSPSetUp(ksp_), "KSPSetUp (the preconditioner's set-up)");
    if (finest_smoother_) {  // the method's own preconditioner
      const auto rows = static_cast<PetscInt>(matrix.rows());
      check(finest_smoother_.install(preconditioner, matrix, columns_in_petsc_order(rows), !share_row_owners_.empty()),
            "the finest level's smoother");
    }
  }

  long solve_system(const Eigen::VectorXd& rhs, Eigen::VectorXd& solution) override {
    PetscScalar* values;
    check(VecGetArray(rhs_, &values), "VecGetArray");
    for (PetscInt row = first_row_; row < last_row_; ++row) values[row - first_row_] = rhs[method_index(row)];
    check(VecRestoreArray(rhs_, &values), "VecRestoreArray");
    check(KSPSolve(ksp_, rhs_, solution_), "KSPSolve");
    if (!reported_unused_options_) report_unused_options();
    KSPConvergedReason reason;
    PetscInt iterations;
    check(KSPGetConvergedReason(ksp_, &reason), "KSPGetConvergedReason");
    check(KSPGetIterationNumber(ksp_, &iterations), "KSPGetIterationNumber");
    if (reason < 0) {
      PetscReal residual = 0;
      KSPGetResidualNorm(ksp_, &residual);
      std::ostringstream message;
      message << "PETSc " << petsc::method_names(ksp_) << " did not converge: " << KSPConvergedReasons[reason]
              << " after " << iterations << " iterations (residual norm " << residual << ", right-hand side "
              << rhs.norm() << ")";
      throw NumericalError(message.str());
    }
    // Every rank gets the whole solution: the integrators run on every rank.
    Vec whole = solution_;
    if (ranks::distributed()) {
      check(VecScatterBegin(gather_, solution_, gathered_, INSERT_VALUES, SCATTER_FORWARD), "VecScatterBegin");
      check(VecScatterEnd(gather_, solution_, gathered_, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");
      whole = gathered_;
    }
    const PetscScalar* result;
    check(VecGetArrayRead(whole, &result), "VecGetArrayRead");
    solution.resize(rhs.size());
    for (Eigen::Index dof = 0; dof < rhs.size(); ++dof) solution[dof] = result[petsc_index(dof)];
    check(VecRestoreArrayRead(whole, &result), "VecRestoreArrayRead");
    return iterations;
  }

  bool analysed_everywhere(bool here) const override {
    return ranks::distributed() ? ranks::sum(here ? 0.0 : 1.0) == 0 : here;
  }

private:
  // Each rank's share of the sum, on its own pattern (LinearSolverOptions::share_row_owners):
  // rows numbered from the owners, the distributed matrix preallocated from every rank's
  // pattern by PETSc's MATPREALLOCATOR (which sends each rank the entries others add to
  // its rows), so no rank ever holds the whole pattern.
  void analyze_shares(const Eigen::SparseMatrix<double>& matrix) {
    const auto size = static_cast<PetscInt>(matrix.rows());
    number_rows_from_owners(size);
    const PetscInt rows = last_row_ - first_row_;
    check(MatCreate(communicator_, &matrix_), "MatCreate");
    check(MatSetSizes(matrix_, rows, rows, size, size), "MatSetSizes");
    check(MatSetType(matrix_, MATMPIAIJ), "MatSetType");
    check(MatSetBlockSize(matrix_, 3), "MatSetBlockSize");
    Mat preallocator;
    check(MatCreate(communicator_, &preallocator), "MatCreate");
    check(MatSetSizes(preallocator, rows, rows, size, size), "MatSetSizes");
    check(MatSetType(preallocator, MATPREALLOCATOR), "MatSetType");
    check(MatSetBlockSize(preallocator, 3), "MatSetBlockSize");
    check(MatSetUp(preallocator), "MatSetUp");
    for_each_row_of_share(matrix, [&](PetscInt row, PetscInt count, const PetscInt* columns, const double* values) {
      check(MatSetValues(preallocator, 1, &row, count, columns, values, INSERT_VALUES), "MatSetValues");
    });
    check(MatAssemblyBegin(preallocator, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
    check(MatAssemblyEnd(preallocator, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
    const PetscErrorCode preallocating = MatPreallocatorPreallocate(preallocator, PETSC_TRUE, matrix_);
    MatDestroy(&preallocator);
    check(preallocating, "MatPreallocatorPreallocate");
    // Later assemblies add other ranks' rows too, and never a new entry.
    check(MatSetOption(matrix_, MAT_NO_OFF_PROC_ENTRIES, PETSC_FALSE), "MatSetOption");
    check(MatSetOption(matrix_, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE), "MatSetOption");
    create_vectors(size);
  }

  // body(PETSc row, count, PETSc columns, values) for every column of a share: the
  // Hessian of an energy (with the mass and the eliminated conditions) is symmetric, so
  // column c of Eigen's compressed columns is row c, handed to PETSc without a transposed copy.
  template <typename Body>
  void for_each_row_of_share(const Eigen::SparseMatrix<double>& matrix, Body&& body) {
    const int* starts = matrix.outerIndexPtr();
    const int* rows = matrix.innerIndexPtr();
    for (Eigen::Index column = 0; column < matrix.outerSize(); ++column) {
      const int first = starts[column], count = starts[column + 1] - first;
      row_buffer_.resize(static_cast<size_t>(count));
      for (int k = 0; k < count; ++k) row_buffer_[k] = petsc_index(rows[first + k]);
      body(petsc_index(column), count, row_buffer_.data(), matrix.valuePtr() + first);
    }
  }

  // The solution and right-hand side vectors (this rank's rows), the gather of the
  // solution to every rank, and the near-null space.
  void create_vectors(PetscInt size) {
    const PetscInt rows = last_row_ - first_row_;
    if (ranks::distributed()) {
      check(VecCreateMPI(communicator_, rows, size, &rhs_), "VecCreateMPI");
      check(VecScatterCreateToAll(rhs_, &gather_, &gathered_), "VecScatterCreateToAll");
    } else {
      check(VecCreateSeq(PETSC_COMM_SELF, size, &rhs_), "VecCreateSeq");
    }
    check(VecDuplicate(rhs_, &solution_), "VecDuplicate");
    if (near_null_space_.cols() > 0) set_near_null_space(size);
  }

  // Blocks of three rows numbered rank by rank, in the method's order within a rank.
  void number_rows_from_owners(PetscInt size) {
    const size_t blocks = static_cast<size_t>(size / 3);
    if (size % 3 != 0 || share_row_owners_.size() != blocks)
      throw std::logic_error("petsc solver: " + std::to_string(share_row_owners_.size()) + " row owners for " +
                             std::to_string(size) + " rows");
    std::vector<PetscInt> starts(static_cast<size_t>(ranks::count()) + 1, 0);
    for (int owner : share_row_owners_) ++starts[owner + 1];
    for (int rank = 0; rank < ranks::count(); ++rank) starts[rank + 1] += starts[rank];
    first_row_ = 3 * starts[ranks::index()];
    last_row_ = 3 * starts[ranks::index() + 1];
    petsc_of_method_.resize(static_cast<size_t>(size));
    method_of_petsc_.resize(static_cast<size_t>(size));
    for (size_t block = 0; block < blocks; ++block) {
      const PetscInt target = starts[share_row_owners_[block]]++;
      for (PetscInt k = 0; k < 3; ++k) {
        petsc_of_method_[3 * block + k] = 3 * target + k;
        method_of_petsc_[3 * target + k] = static_cast<PetscInt>(3 * block + k);
      }
    }
  }

  // Over several ranks PETSc's rows are METIS's parts of the matrix graph (partitioned_rows);
  // on one they are the method's.
  void number_rows(const Eigen::SparseMatrix<double>& matrix, PetscInt block) {
    petsc_of_method_.clear();
    method_of_petsc_.clear();
    if (!ranks::distributed()) {
      first_row_ = 0;
      last_row_ = static_cast<PetscInt>(matrix.rows());
      return;
    }
    const PartitionedRows rows = partitioned_rows(matrix, static_cast<int>(block));
    first_row_ = static_cast<PetscInt>(rows.first_row);
    last_row_ = static_cast<PetscInt>(rows.last_row);
    petsc_of_method_.assign(rows.new_of_old.begin(), rows.new_of_old.end());
    method_of_petsc_.assign(rows.old_of_new.begin(), rows.old_of_new.end());
  }
  PetscInt petsc_index(Eigen::Index dof) const {
    return petsc_of_method_.empty() ? static_cast<PetscInt>(dof) : petsc_of_method_[dof];
  }
  Eigen::Index method_index(PetscInt row) const { return method_of_petsc_.empty() ? row : method_of_petsc_[row]; }
  // The method's columns in order of their PETSc index.
  std::vector<Eigen::Index> columns_in_petsc_order(PetscInt size) const {
    std::vector<Eigen::Index> order(static_cast<size_t>(size));
    for (PetscInt row = 0; row < size; ++row) order[row] = method_index(row);
    return order;
  }

  void destroy_arrays() {
    MatDestroy(&matrix_);
    VecDestroy(&rhs_);
    VecDestroy(&solution_);
    VecScatterDestroy(&gather_);
    VecDestroy(&gathered_);
  }

  void set_near_null_space(PetscInt size) {
    if (near_null_space_.rows() != size)
      throw std::logic_error("petsc solver: near-null space has " + std::to_string(near_null_space_.rows()) +
                             " rows, the matrix " + std::to_string(size));
    std::vector<Vec> vectors(near_null_space_.cols());
    for (Eigen::Index mode = 0; mode < near_null_space_.cols(); ++mode) {
      check(VecDuplicate(rhs_, &vectors[mode]), "VecDuplicate");
      PetscScalar* values;
      check(VecGetArray(vectors[mode], &values), "VecGetArray");
      for (PetscInt row = first_row_; row < last_row_; ++row)
        values[row - first_row_] = near_null_space_(method_index(row), mode);
      check(VecRestoreArray(vectors[mode], &values), "VecRestoreArray");
    }
    MatNullSpace space;
    check(MatNullSpaceCreate(communicator_, PETSC_FALSE, static_cast<PetscInt>(vectors.size()), vectors.data(), &space),
          "MatNullSpaceCreate");
    check(MatSetNearNullSpace(matrix_, space), "MatSetNearNullSpace");
    MatNullSpaceDestroy(&space);  // the matrix holds its own reference, as the space holds the vectors'
    for (Vec& vector : vectors) VecDestroy(&vector);
  }

  // PETSc ignores an option nobody asked for (a misspelling, or one of a type not
  // chosen); the first set-up and solve have asked for all of them (a solve reads its
  // monitors and -ksp_converged_reason), so say which they did not use.
  void report_unused_options() {
    reported_unused_options_ = true;
    const std::string unused = petsc::unused_options(prefix_);
    if (!unused.empty())
      std::cerr << "altfem: warning: solver.petsc_options: PETSc (" << petsc::method_names(ksp_) << ") did not use "
                << unused << "\n";
  }

  MPI_Comm communicator_ = PETSC_COMM_SELF;  // PETSC_COMM_WORLD over several ranks
  std::string prefix_;
  std::vector<std::string> option_names_;  // with the prefix, without the leading "-"
  Eigen::MatrixXd near_null_space_;        // orthonormal columns
  KSP ksp_ = nullptr;
  Mat matrix_ = nullptr;
  Vec rhs_ = nullptr;
  Vec solution_ = nullptr;
  VecScatter gather_ = nullptr;  // over several ranks: the solution to every rank
  Vec gathered_ = nullptr;
  PetscInt first_row_ = 0, last_row_ = 0;  // this rank's rows, in PETSc's numbering
  // Over several ranks, the DOFs' PETSc numbering (number_rows) both ways; empty on one.
  std::vector<PetscInt> petsc_of_method_, method_of_petsc_;
  std::vector<PetscInt> row_starts_;   // this rank's #rows + 1
  std::vector<PetscInt> columns_;      // this rank's #nonzeros, global column indices
  std::vector<PetscScalar> values_;    // this rank's #nonzeros: on one rank the matrix's own values
  std::vector<int> csr_from_csc_;      // this rank's #nonzeros: the Eigen value index of each AIJ entry
  std::vector<int> share_row_owners_;  // over several ranks, for shares: each block row's rank
  std::vector<PetscInt> row_buffer_;   // for_each_row_of_share's columns of one row
  bool reported_unused_options_ = false;
  FinestLevelSmoother finest_smoother_{{}};  // the method's preconditioner (petsc_finest_smoother.hpp)
  FirstOrderCoarseLevel coarse_level_;  // a coarser space's level, where the method has one (petsc_coarse_level.hpp)
};

}  // namespace

bool petsc_available() { return true; }

std::string petsc_version() {
  std::string version = std::to_string(PETSC_VERSION_MAJOR) + "." + std::to_string(PETSC_VERSION_MINOR) + "." +
                        std::to_string(PETSC_VERSION_SUBMINOR);
  std::string packages;
#ifdef PETSC_HAVE_HYPRE
  packages += "hypre";
#endif
#ifdef PETSC_HAVE_MUMPS
  packages += packages.empty() ? "MUMPS" : " and MUMPS";
#endif
  return packages.empty() ? version : version + ", with " + packages;
}

std::unique_ptr<LinearSolver> make_petsc_solver(const LinearSolverOptions& options) {
  return std::make_unique<PetscSolver>(options);
}

}  // namespace altfem

#else

namespace altfem {

bool petsc_available() { return false; }

std::string petsc_version() { return {}; }

std::unique_ptr<LinearSolver> make_petsc_solver(const LinearSolverOptions&) {
  throw InputError(
      "solver.linear: \"petsc\" needs a build with PETSc (CMake -DALTFEM_PETSC=ON, Debian package "
      "libpetsc-real3.18-dev)");
}

}  // namespace altfem

#endif
