#pragma once
// PETSc's Krylov solvers and preconditioners (KSP, PC) as one of altfem's linear solvers:
// solver.linear "petsc" (docs/scene-schema.md, "Solver"). On one process PETSc works on
// altfem's own arrays; over several ranks (docs/scaling.md) on a distributed matrix that
// sums each rank's share (LinearSolverOptions::share_row_owners) or takes each rank's rows
// of the whole. PETSc's start and error codes: petsc_session.hpp. The default is
// CG + GAMG, PETSc's smoothed-aggregation algebraic multigrid, given the rigid-body modes
// as the near-null space (MatSetNearNullSpace): for elasticity, aggregation that knows
// only translations builds coarse spaces that cannot rotate, and its iterations grow
// with refinement (Vaněk, Mandel & Brezina 1996; Adams 2004). hypre's BoomerAMG, MUMPS
// and every other PETSc solver are one options string away.
#include "shared/solve/linear_solver.hpp"

namespace altfem {

/// Whether this build has PETSc (CMake option ALTFEM_PETSC).
bool petsc_available();
/// "3.18.5, with hypre and MUMPS": the PETSc this build has; empty without PETSc.
std::string petsc_version();

/// The PETSc solver `options` describe (options.petsc_options, near_null_space,
/// tolerance, max_iterations). The matrix is copied into a PETSc AIJ matrix of block
/// size 3 once per sparsity pattern and its values refreshed in place afterwards;
/// factorize() sets the preconditioner up (counted as a factorisation). solve() throws
/// NumericalError naming PETSc's reason when the Krylov method does not converge.
/// Options PETSc did not use are reported once on stderr after the first set-up.
/// Throws InputError in a build without PETSc.
std::unique_ptr<LinearSolver> make_petsc_solver(const LinearSolverOptions& options);

}  // namespace altfem
