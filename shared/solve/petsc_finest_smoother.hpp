#pragma once
// A method's own preconditioner as the smoother of the finest level of PETSc's algebraic
// multigrid, on one process. fcm's cut cells leave functions whose support holds a
// sliver of material: their energy is tiny and local, so neither GAMG's point smoother
// (Chebyshev on the diagonal) nor its coarse spaces (smooth aggregates) reduce it, and CG
// takes about 1,100 iterations on the half-ball's 8 × 8 × 4 Hex20 grid (89 with this). The Additive
// Schwarz blocks of the small cut cells (Longva et al. 2020 §5.2) invert exactly that
// energy; as the fine smoother they leave GAMG the smooth error it reduces well.
#ifdef ALTFEM_HAVE_PETSC
#include <petscksp.h>

#include <Eigen/Core>
#include <vector>

#include "shared/solve/preconditioner.hpp"

namespace altfem {

/// Makes `preconditioner` (computed on the matrix `pc` holds, in the method's numbering)
/// the preconditioner of the finest level's smoother of `pc`, a PCMG or PCGAMG already set
/// up; its Chebyshev iteration then estimates the spectrum it preconditions. Row r of
/// PETSc's vectors is DOF method_of_row[r] of the method's. Both must outlive `pc`'s use.
/// Returns PETSc's error code (0: done); a `pc` that is not multigrid is left alone.
PetscErrorCode set_finest_smoother(PC pc, const Preconditioner& preconditioner,
                                   const std::vector<Eigen::Index>& method_of_row);

}  // namespace altfem
#endif
