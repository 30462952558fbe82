#pragma once
// Test matrices for the linear solvers, all stored with both triangles.
#include <Eigen/Sparse>

namespace altfem::testing {

/// The 7-point Laplacian of an n × n × n grid with Dirichlet boundary,
/// Kronecker-multiplied by the 3 × 3 SPD block I + ½·11ᵀ so that each node has
/// three coupled unknowns like elasticity: SPD, 3n³ × 3n³.
Eigen::SparseMatrix<double> elasticity_like_laplacian(int n);

/// `matrix` − shift · I: indefinite when the shift lies inside the spectrum. For
/// elasticity_like_laplacian(6 or 8) the shift 2.7 is ≥ 0.05 away from every
/// eigenvalue (condition numbers 183 and 448).
Eigen::SparseMatrix<double> shifted(const Eigen::SparseMatrix<double>& matrix, double shift);

/// The quasi-definite saddle-point matrix [[A, Bᵀ], [B, −c·I]] with A =
/// elasticity_like_laplacian(n) and B (m × 3n³) summing groups of unknowns.
Eigen::SparseMatrix<double> saddle_point(int n, int constraints, double c);

}  // namespace altfem::testing
