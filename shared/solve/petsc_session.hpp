#pragma once
// What altfem's PETSc objects need before anything else (petsc_solver.cpp): PETSc started
// once per process without its signal and error handlers, its error codes turned into
// exceptions, and each solver's options under a prefix of its own. Only in a build with
// PETSc (ALTFEM_HAVE_PETSC).
#ifdef ALTFEM_HAVE_PETSC

#include <petscksp.h>

#include <string>
#include <vector>

namespace altfem::petsc {

/// PETSc's message for `code` and the specific one of its last error.
std::string error_text(PetscErrorCode code);
/// Throws NumericalError naming `call` and PETSc's message when `code` is not 0.
void check(PetscErrorCode code, const char* call);
/// Starts PETSc (and MPI as a singleton when mpirun did not) on the first call; it stops at exit.
void start();
/// "altfem1_", "altfem2_", …: a new options prefix for each solver.
std::string next_prefix();
/// `options` with the prefix given to every option name ("-pc_type gamg" → "-altfem1_pc_type
/// gamg"); each prefixed name, without its "-", is appended to `names`.
std::string prefixed_options(const std::string& options, const std::string& prefix, std::vector<std::string>& names);
/// Whether the options database chooses how the GAMG under `prefix` coarsens its finest
/// level (-pc_gamg_aggressive_coarsening, or its deprecated alias -pc_gamg_square_graph).
bool coarsening_chosen(const std::string& prefix);
/// Sets the GAMG `pc`'s aggregation to drop graph edges weaker than 0.05, altfem's default
/// for every GAMG it sets up; options read after it (-pc_gamg_threshold) still choose.
PetscErrorCode set_aggregation_threshold(PC pc);
/// "cg + gamg": the Krylov method's and the preconditioner's types, for messages.
std::string method_names(KSP ksp);
/// The options under `prefix` that nobody has asked for ("-name, -name", without the
/// prefix; empty: none).
std::string unused_options(const std::string& prefix);

}  // namespace altfem::petsc

#endif
