#pragma once
// Projection of a symmetric matrix onto the positive (semi-)definite cone by
// eigenvalue clamping: H = Q Λ Qᵀ → Q max(Λ, m) Qᵀ, the nearest matrix in the
// Frobenius norm with eigenvalues ≥ m. Newton on a non-convex energy (inverted
// or buckling elements) needs it for a descent direction (Teran, Sifakis,
// Irving & Fedkiw 2005, "Robust quasistatic finite elements and flesh simulation").
#include <Eigen/Core>

#include "shared/material/material.hpp"

namespace altfem {

/// Clamps the eigenvalues of `symmetric` (n × n; only its lower triangle is read)
/// to ≥ minimum_eigenvalue, in place. A matrix whose eigenvalues all already are
/// ≥ minimum_eigenvalue is left untouched, bit for bit. Throws NumericalError if
/// an entry is not finite. Allocates (dynamic size): meant for element matrices.
void project_to_spd(Eigen::Ref<Eigen::MatrixXd> symmetric, double minimum_eigenvalue = 0.0);

/// The same for a per-quadrature-point 9 × 9 tangent dP/dF; allocation-free.
void project_to_spd(Matrix9d& symmetric, double minimum_eigenvalue = 0.0);

}  // namespace altfem
