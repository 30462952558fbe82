#pragma once
// CHOLMOD (SuiteSparse) sparse Cholesky through its C API: Eigen's
// CholmodSupport hides the failing column and allocates on every solve.
#include "shared/solve/linear_solver.hpp"

namespace altfem {

enum class CholmodFactorisation {
  /// LLᵀ with BLAS-3 supernodes: the fast path for SPD matrices.
  supernodal_llt,
  /// Simplicial LDLᵀ without pivoting: works for quasi-definite matrices
  /// (Vanderbei 1995: [[A, Bᵀ], [B, −C]] with A, C SPD factorise stably in any
  /// symmetric order), e.g. saddle-point systems with a regularised (2,2) block.
  simplicial_ldlt,
};

enum class CholmodIndices {
  /// int indices, switching to SuiteSparse_long when the factor outgrows them (2^31 entries)
  automatic,
  /// SuiteSparse_long from the start (what the switch leads to; for tests)
  wide,
};

/// A CHOLMOD solver; reads only the lower triangle of the matrices it is given.
/// factorize() throws NumericalError "matrix is not positive definite (CHOLMOD
/// status 1, column k)" (LLᵀ) or "... has a zero pivot ..." (LDLᵀ), and, before
/// computing it, "the Cholesky factor needs … GB …" when the factor will not fit in
/// the memory available (factor_memory.hpp).
std::unique_ptr<LinearSolver> make_cholmod_solver(CholmodFactorisation factorisation,
                                                  CholmodIndices indices = CholmodIndices::automatic);

}  // namespace altfem
