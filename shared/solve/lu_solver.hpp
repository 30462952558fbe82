#pragma once
#include "shared/solve/linear_solver.hpp"

namespace altfem {

/// General sparse LU with partial pivoting: UMFPACK (SuiteSparse) through
/// Eigen's UmfPackLU. For indefinite systems that are not quasi-definite
/// (neither CHOLMOD nor Eigen pivots a sparse LDLᵀ). Reads the whole matrix.
/// factorize() throws NumericalError when UMFPACK finds the matrix singular.
std::unique_ptr<LinearSolver> make_lu_solver();

}  // namespace altfem
