#pragma once
#include "shared/solve/krylov.hpp"
#include "shared/solve/linear_solver.hpp"

namespace altfem {

/// A Krylov solver (`kind` is pcg, minres or conjugate_residual) as a
/// LinearSolver: factorize() keeps a copy of the matrix and computes the
/// preconditioner; every solve starts from x = 0. Throws std::logic_error for
/// a direct `kind`.
std::unique_ptr<LinearSolver> make_iterative_solver(LinearSolverKind kind,
                                                    std::unique_ptr<Preconditioner> preconditioner,
                                                    const KrylovSettings& settings);

}  // namespace altfem
