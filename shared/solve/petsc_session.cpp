#include "shared/solve/petsc_session.hpp"

#ifdef ALTFEM_HAVE_PETSC

#include <atomic>
#include <cctype>
#include <sstream>

#include "shared/common/error.hpp"

namespace altfem::petsc {

// PETSc's error text: its generic message for the code and the specific one of the last SETERRQ.
std::string error_text(PetscErrorCode code) {
  const char* text = nullptr;
  char* specific = nullptr;
  PetscErrorMessage(code, &text, &specific);
  std::string message = text ? text : "error " + std::to_string(code);
  if (specific && *specific) message += std::string(": ") + specific;
  return message;
}

void check(PetscErrorCode code, const char* call) {
  if (code != 0) throw NumericalError(std::string("PETSc: ") + call + " failed: " + error_text(code));
}

// PETSc (and MPI, as a singleton when the process was not started by mpirun) starts with
// the first PETSc solver and stops at exit. PETSc's signal handlers would take SIGSEGV
// and SIGFPE from the rest of altfem, and its error handler would print tracebacks:
// errors come back as codes and become exceptions here.
void start() {
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

bool coarsening_chosen(const std::string& prefix) {
  PetscBool aggressive = PETSC_FALSE, squared = PETSC_FALSE;
  PetscOptionsHasName(nullptr, prefix.c_str(), "-pc_gamg_aggressive_coarsening", &aggressive);
  PetscOptionsHasName(nullptr, prefix.c_str(), "-pc_gamg_square_graph", &squared);
  return aggressive || squared;
}

// PETSc's manual suggests 0.01-0.05 for elasticity; its default, 0, keeps every edge.
// With 0.05 the cantilever's Hex20 20 × 2 × 2 took 29 iterations on its first-order level
// against 32 with 0, Tet10 40 × 4 × 4 30 against 33; on the whole space the Hex8
// cantilever 26 at 1,048,707 DOFs against 39 (23 at 139,587: docs/performance.md).
PetscErrorCode set_aggregation_threshold(PC pc) {
  PetscReal threshold = 0.05;
  return PCGAMGSetThreshold(pc, &threshold, 1);
}

std::string method_names(KSP ksp) {
  KSPType method;
  PCType preconditioner_type;
  PC preconditioner;
  KSPGetType(ksp, &method);
  KSPGetPC(ksp, &preconditioner);
  PCGetType(preconditioner, &preconditioner_type);
  return std::string(method) + " + " + preconditioner_type;
}

std::string unused_options(const std::string& prefix) {
  PetscInt count = 0;
  char** names = nullptr;
  char** values = nullptr;
  if (PetscOptionsLeftGet(nullptr, &count, &names, &values) != 0) return {};
  std::string unused;
  for (PetscInt index = 0; index < count; ++index) {
    const std::string name = names[index];
    if (name.rfind(prefix, 0) == 0) unused += (unused.empty() ? "-" : ", -") + name.substr(prefix.size());
  }
  PetscOptionsLeftRestore(nullptr, &count, &names, &values);
  return unused;
}

}  // namespace altfem::petsc

#endif
