#pragma once
// Whether DG's stiffness is positive definite: Kaufmann et al. 2009 §8 double the penalty
// η until it is ("start with a low value and double it until K is positive definite").
#include <vector>

#include "dg/dg_linear_system.hpp"

namespace altfem::dg {

/// K positive definite, up to its rigid motions when no condition holds the body: is
/// K + δM, δ = 1e-10 · max K_ii / max M_ii? With a direct solver, by its Cholesky factor
/// (CHOLMOD). With an iterative one the run needs no factor, and this test's was the
/// run's largest allocation (20 GB at 768k DOFs, issue #35): block-Jacobi PCG on a random
/// right-hand side decides instead. Its curvatures pᵀAp are, up to positive factors, the
/// pivots of the Lanczos tridiagonal T_k (Golub & Van Loan, Matrix Computations, §11.3.5),
/// so PCG breaks down as soon as a Ritz value of K + δM falls below 0, which happens before
/// the residual's component along a negative eigenvector can shrink: an indefinite matrix
/// breaks PCG down before it converges; the cell blocks, principal submatrices, are
/// positive definite when K + δM is. A PCG that neither converges nor breaks down within
/// its iterations decides nothing, and the factorisation does.
bool positive_definite(const DgLinearSystem& system, const std::vector<std::vector<int>>& element_dofs, bool iterative);

}  // namespace altfem::dg
