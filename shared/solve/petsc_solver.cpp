#include "shared/solve/petsc_solver.hpp"

#include "shared/common/error.hpp"

#ifdef ALTFEM_HAVE_PETSC

#include <petscksp.h>

#include <Eigen/QR>
#include <atomic>
#include <cctype>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace altfem {
namespace {

// PETSc's error text: its generic message for the code and the specific one of the last SETERRQ.
std::string petsc_error_text(PetscErrorCode code) {
  const char* text = nullptr;
  char* specific = nullptr;
  PetscErrorMessage(code, &text, &specific);
  std::string message = text ? text : "error " + std::to_string(code);
  if (specific && *specific) message += std::string(": ") + specific;
  return message;
}

void check(PetscErrorCode code, const char* call) {
  if (code != 0) throw NumericalError(std::string("PETSc: ") + call + " failed: " + petsc_error_text(code));
}

// PETSc (and MPI, as a singleton when the process was not started by mpirun) starts with
// the first PETSc solver and stops at exit. PETSc's signal handlers would take SIGSEGV
// and SIGFPE from the rest of altfem, and its error handler would print tracebacks:
// errors come back as codes and become exceptions here.
void start_petsc() {
  struct Session {
    Session() {
      PetscOptionsSetValue(nullptr, "-no_signal_handler", nullptr);
      check(PetscInitializeNoArguments(), "PetscInitialize");
      PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
    }
    ~Session() { PetscFinalize(); }
  };
  static Session session;
}

// Each solver reads its options under a prefix of its own in PETSc's one options database,
// so that two solvers in one process (a run and its rebuild after an event) do not share them.
std::string next_prefix() {
  static std::atomic<int> count{0};
  return "altfem" + std::to_string(++count) + "_";
}

// The options string with every option name (a token "-" followed by a letter, not a
// negative number) given the prefix: "-pc_type gamg" → "-altfem1_pc_type gamg".
std::string prefixed_options(const std::string& options, const std::string& prefix, std::vector<std::string>& names) {
  std::istringstream tokens(options);
  std::string token, result;
  while (tokens >> token) {
    if (token.size() > 1 && token[0] == '-' && std::isalpha(static_cast<unsigned char>(token[1]))) {
      names.push_back(prefix + token.substr(1));
      token = "-" + names.back();
    }
    result += token + " ";
  }
  return result;
}

class PetscSolver final : public LinearSolver {
public:
  explicit PetscSolver(const LinearSolverOptions& options) : prefix_(next_prefix()) {
    start_petsc();
    if (options.near_null_space.cols() > 0) {
      // MatNullSpaceCreate wants orthonormal vectors.
      const Eigen::HouseholderQR<Eigen::MatrixXd> qr(options.near_null_space);
      near_null_space_ = qr.householderQ() * Eigen::MatrixXd::Identity(options.near_null_space.rows(),
                                                                         options.near_null_space.cols());
    }
    check(KSPCreate(PETSC_COMM_SELF, &ksp_), "KSPCreate");
    check(KSPSetOptionsPrefix(ksp_, prefix_.c_str()), "KSPSetOptionsPrefix");
    check(KSPSetType(ksp_, KSPCG), "KSPSetType");
    PC preconditioner;
    check(KSPGetPC(ksp_, &preconditioner), "KSPGetPC");
    check(PCSetType(preconditioner, PCGAMG), "PCSetType");
    check(KSPSetTolerances(ksp_, options.tolerance, 0.0, PETSC_DEFAULT, options.max_iterations), "KSPSetTolerances");
    const std::string inserted = prefixed_options(options.petsc_options, prefix_, option_names_);
    const PetscErrorCode inserting = PetscOptionsInsertString(nullptr, inserted.c_str());
    const PetscErrorCode reading = inserting ? inserting : KSPSetFromOptions(ksp_);
    if (reading)
      throw InputError("solver.petsc_options: \"" + options.petsc_options + "\": " + petsc_error_text(reading));
    // CG stops by altfem's criterion for every iterative solver, ‖b − A x‖ ≤ tolerance ‖b‖,
    // unless the options say otherwise; a method that cannot measure that norm with its
    // preconditioner's side (GMRES preconditioned on the left) keeps PETSc's default.
    KSPType method;
    check(KSPGetType(ksp_, &method), "KSPGetType");
    const bool norm_chosen = options.petsc_options.find("-ksp_norm_type") != std::string::npos;
    if (!norm_chosen && std::string(method) == KSPCG)
      check(KSPSetNormType(ksp_, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
  }

  ~PetscSolver() override {
    for (const std::string& name : option_names_) PetscOptionsClearValue(nullptr, ("-" + name).c_str());
    KSPDestroy(&ksp_);
    MatDestroy(&matrix_);
    VecDestroy(&rhs_);
    VecDestroy(&solution_);
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
    MatDestroy(&matrix_);
    VecDestroy(&rhs_);
    VecDestroy(&solution_);
    const auto size = static_cast<PetscInt>(matrix.rows());
    row_starts_.assign(size + 1, 0);
    for (Eigen::Index column = 0; column < matrix.outerSize(); ++column)
      for (Eigen::SparseMatrix<double>::InnerIterator entry(matrix, column); entry; ++entry) ++row_starts_[entry.row() + 1];
    for (PetscInt row = 0; row < size; ++row) row_starts_[row + 1] += row_starts_[row];
    columns_.resize(row_starts_[size]);
    csr_from_csc_.resize(row_starts_[size]);
    std::vector<PetscInt> next(row_starts_.begin(), row_starts_.end() - 1);
    // Columns in increasing order, so every row's column indices come out sorted, as AIJ needs.
    for (Eigen::Index column = 0; column < matrix.outerSize(); ++column)
      for (Eigen::SparseMatrix<double>::InnerIterator entry(matrix, column); entry; ++entry) {
        const PetscInt position = next[entry.row()]++;
        columns_[position] = static_cast<PetscInt>(column);
        csr_from_csc_[position] = static_cast<int>(&entry.value() - matrix.valuePtr());
      }

    values_.assign(columns_.size(), 0.0);
    check(MatCreateSeqAIJWithArrays(PETSC_COMM_SELF, size, size, row_starts_.data(), columns_.data(), values_.data(),
                                    &matrix_),
          "MatCreateSeqAIJWithArrays");
    // Three DOFs per basis function: GAMG aggregates whole functions, as elasticity needs.
    if (size % 3 == 0) check(MatSetBlockSize(matrix_, 3), "MatSetBlockSize");
    check(VecCreateSeq(PETSC_COMM_SELF, size, &rhs_), "VecCreateSeq");
    check(VecDuplicate(rhs_, &solution_), "VecDuplicate");
    if (near_null_space_.cols() > 0) set_near_null_space(size);
  }

  void factorize_values(const Eigen::SparseMatrix<double>& matrix) override {
    PetscScalar* values;
    check(MatSeqAIJGetArray(matrix_, &values), "MatSeqAIJGetArray");
    const double* source = matrix.valuePtr();
    for (std::size_t position = 0; position < csr_from_csc_.size(); ++position)
      values[position] = source[csr_from_csc_[position]];
    check(MatSeqAIJRestoreArray(matrix_, &values), "MatSeqAIJRestoreArray");
    check(KSPSetOperators(ksp_, matrix_, matrix_), "KSPSetOperators");
    check(KSPSetUp(ksp_), "KSPSetUp (the preconditioner's set-up)");
    if (!reported_unused_options_) report_unused_options();
  }

  long solve_system(const Eigen::VectorXd& rhs, Eigen::VectorXd& solution) override {
    PetscScalar* values;
    check(VecGetArray(rhs_, &values), "VecGetArray");
    std::copy(rhs.data(), rhs.data() + rhs.size(), values);
    check(VecRestoreArray(rhs_, &values), "VecRestoreArray");
    check(KSPSolve(ksp_, rhs_, solution_), "KSPSolve");
    KSPConvergedReason reason;
    PetscInt iterations;
    check(KSPGetConvergedReason(ksp_, &reason), "KSPGetConvergedReason");
    check(KSPGetIterationNumber(ksp_, &iterations), "KSPGetIterationNumber");
    if (reason < 0) {
      PetscReal residual = 0;
      KSPGetResidualNorm(ksp_, &residual);
      std::ostringstream message;
      message << "PETSc " << method_names() << " did not converge: " << KSPConvergedReasons[reason] << " after "
              << iterations << " iterations (residual norm " << residual << ", right-hand side " << rhs.norm() << ")";
      throw NumericalError(message.str());
    }
    const PetscScalar* result;
    check(VecGetArrayRead(solution_, &result), "VecGetArrayRead");
    solution = Eigen::Map<const Eigen::VectorXd>(result, rhs.size());
    check(VecRestoreArrayRead(solution_, &result), "VecRestoreArrayRead");
    return iterations;
  }

private:
  void set_near_null_space(PetscInt size) {
    if (near_null_space_.rows() != size)
      throw std::logic_error("petsc solver: near-null space has " + std::to_string(near_null_space_.rows()) +
                             " rows, the matrix " + std::to_string(size));
    std::vector<Vec> vectors(near_null_space_.cols());
    for (Eigen::Index mode = 0; mode < near_null_space_.cols(); ++mode) {
      check(VecCreateSeq(PETSC_COMM_SELF, size, &vectors[mode]), "VecCreateSeq");
      PetscScalar* values;
      check(VecGetArray(vectors[mode], &values), "VecGetArray");
      Eigen::Map<Eigen::VectorXd>(values, size) = near_null_space_.col(mode);
      check(VecRestoreArray(vectors[mode], &values), "VecRestoreArray");
    }
    MatNullSpace space;
    check(MatNullSpaceCreate(PETSC_COMM_SELF, PETSC_FALSE, static_cast<PetscInt>(vectors.size()), vectors.data(), &space),
          "MatNullSpaceCreate");
    check(MatSetNearNullSpace(matrix_, space), "MatSetNearNullSpace");
    MatNullSpaceDestroy(&space);  // the matrix holds its own reference, as the space holds the vectors'
    for (Vec& vector : vectors) VecDestroy(&vector);
  }

  std::string method_names() const {
    KSPType method;
    PCType preconditioner_type;
    PC preconditioner;
    KSPGetType(ksp_, &method);
    KSPGetPC(ksp_, &preconditioner);
    PCGetType(preconditioner, &preconditioner_type);
    return std::string(method) + " + " + preconditioner_type;
  }

  // PETSc ignores an option nobody asked for (a misspelling, or one of a type not
  // chosen); the first set-up has asked for all of them, so say which it did not use.
  void report_unused_options() {
    reported_unused_options_ = true;
    PetscInt count = 0;
    char** names = nullptr;
    char** values = nullptr;
    if (PetscOptionsLeftGet(nullptr, &count, &names, &values) != 0) return;
    std::string unused;
    for (PetscInt index = 0; index < count; ++index) {
      const std::string name = names[index];
      if (name.rfind(prefix_, 0) == 0) unused += (unused.empty() ? " -" : ", -") + name.substr(prefix_.size());
    }
    PetscOptionsLeftRestore(nullptr, &count, &names, &values);
    if (!unused.empty())
      std::cerr << "altfem: warning: solver.petsc_options: PETSc (" << method_names() << ") did not use" << unused
                << "\n";
  }

  std::string prefix_;
  std::vector<std::string> option_names_;  // with the prefix, without the leading "-"
  Eigen::MatrixXd near_null_space_;        // orthonormal columns
  KSP ksp_ = nullptr;
  Mat matrix_ = nullptr;
  Vec rhs_ = nullptr;
  Vec solution_ = nullptr;
  std::vector<PetscInt> row_starts_;  // #dofs + 1
  std::vector<PetscInt> columns_;     // #nonzeros
  std::vector<PetscScalar> values_;   // #nonzeros: the matrix's values, which PETSc does not copy
  std::vector<int> csr_from_csc_;     // #nonzeros: the Eigen value index of each AIJ entry
  bool reported_unused_options_ = false;
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
  throw InputError("solver.linear: \"petsc\" needs a build with PETSc (CMake -DALTFEM_PETSC=ON, Debian package "
                   "libpetsc-real3.18-dev)");
}

}  // namespace altfem

#endif
