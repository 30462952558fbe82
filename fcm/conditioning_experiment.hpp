#pragma once
// The conditioning experiment of Longva et al. 2020 §5.4 (Fig. 5): a 4 × 4 × 4 grid over
// [0, 4/3]³ with the box [0, 1 + ε/3]³ embedded, so that the smallest cut cell holds the
// volume fraction ε³; the backward-Euler matrix A = M + Δt² K(u) at u(X) = (X, X, −X),
// Δt = 1/60, u = 0 at X = 0, for Stable Neo-Hookean; and κ(SA) for no preconditioner,
// Jacobi and Additive Schwarz, with the paper's remedies or a face ghost penalty.
#include <vector>

#include "shared/element/element_type.hpp"

namespace altfem::fcm {

struct ConditioningRow {
  double volume_fraction;        ///< of the smallest cut cell, ε³
  double none, jacobi, schwarz;  ///< κ(SA) = max |λ| / min |λ| of S^{1/2} A S^{1/2}
  /// Preconditioned CG iterations to a relative residual of 1e-8 on A x = A 1
  /// (capped at 2000: then CG did not converge).
  int none_iterations, jacobi_iterations, schwarz_iterations;
};

/// The material of the experiment: the paper's E = 3e6 Pa, ν = 0.4 as its published code
/// effectively ran it, with λ four times too small (docs/scenes.md, "Material parameters").
inline constexpr double conditioning_youngs_modulus = 2.679e6;  ///< Pa
inline constexpr double conditioning_poisson_ratio = 0.25;

/// One row per smallest volume fraction 2^-k, for the material above. Any Lagrange cell:
/// hexahedra get exact box rules, tetrahedra intersection rules. Three dense eigenvalue
/// problems per row: seconds per row for Tet10's 2,000 free DOFs. ghost_penalty: γ of
/// FcmOptions::ghost_penalty (0: off), the remedy compared with the paper's.
std::vector<ConditioningRow> conditioning_experiment(ElementType cell, const std::vector<int>& exponents,
                                                     double stabilization, double ghost_penalty = 0);

}  // namespace altfem::fcm
