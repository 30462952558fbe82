#pragma once
// The affine functions inside a DG space of degree k ≥ 2, as the coarse level of PETSc's
// p-multigrid (solver.p_multigrid, shared/solve/petsc_coarse_level.hpp): each cell's
// basis is graded (monomial_index order), so its first four functions, 1 and the three
// scaled coordinates, are the k = 1 space of the same cell, and the coarse operator
// Pᵀ K P is the k = 1 block of K (with k = 2's penalty). GAMG, which took 90-114 CG
// iterations on the whole k = 2 space, took 39-40 on k = 1 (docs/performance.md).
#include "dg/dg_linear_system.hpp"
#include "shared/solve/coarse_space.hpp"

namespace altfem::dg {

/// Coarse function 4c + a is cell c's function a < 4, injected (P's column a unit vector).
/// Empty when the cells hold no more than the affine functions (k = 1), or when strongly
/// imposed conditions recombine some cells' functions (their first four are then no
/// longer the affine monomials).
CoarseSpace affine_coarse_space(const DgLinearSystem& system);

}  // namespace altfem::dg
