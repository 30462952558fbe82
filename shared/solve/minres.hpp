#pragma once
#include "shared/solve/krylov.hpp"

namespace altfem {

/// Vectors (#dofs each) kept between solves so that iterations never allocate.
struct MinresWorkspace {
  Eigen::VectorXd residual, lanczos_previous, lanczos_current, preconditioned, lanczos_vector;
  Eigen::VectorXd direction, direction_previous, direction_before_previous;
};

/// Preconditioned MINRES (Paige & Saunders 1975; the recurrences of Choi, Paige
/// & Saunders 2011, Table 3.1, as in SciPy's minres) for a symmetric, possibly
/// indefinite, nonsingular `matrix` (#dofs × #dofs, both triangles) with an SPD
/// preconditioner (already computed). `solution` (#dofs) holds the initial guess
/// on entry. Stopping rule: krylov.hpp (the recurrence tracks ‖r‖ in the M⁻¹ norm,
/// so the true 2-norm residual decides). Throws NumericalError on
/// non-convergence or when the preconditioner is not positive definite.
KrylovResult minres(const Eigen::SparseMatrix<double>& matrix, const Preconditioner& preconditioner,
                    const Eigen::VectorXd& rhs, Eigen::VectorXd& solution, const KrylovSettings& settings,
                    MinresWorkspace& workspace);

}  // namespace altfem
