#pragma once
// A cell-by-cell proof that interior-penalty DG's K is positive definite (up to the rigid
// motions of a free body), which spares the Cholesky factorisation of the doubling test
// (Kaufmann et al. 2009 §8) whenever the penalty is comfortably large.
//
// The energy of v is a(v, v) = Σ_K a_K(v, v) + Σ_f [−2 ∫_f {σ(v)n}·[[v]] + [[v]]ᵀ T_f [[v]]]
// (eqs. (21), (23)-(26)), T_f = T_f⁻ + T_f⁺ the two sides' shares of the penalty
// (DgLinearSystem::side_penalty). Per side K of f the terms −∫ σ_K(v)n·j + jᵀ T_K j, as a
// function of the jump j, are at least −¼ ∫ (σ_K(v)n)ᵀ T_K⁻¹ σ_K(v)n (complete the
// square); on a Dirichlet face the one side's −2 ∫ σ(v)n·Pv + (Pv)ᵀ T_f Pv is at least
// −∫ (σn)ᵀ (P T_f P)⁺ σn. So a(v, v) ≥ Σ_K [a_K(v, v) − v_Kᵀ N_K v_K], with N_K the sum of
// those trace terms over the cell's faces, and K is positive definite on the
// complement of the rigid motions when every cell's A_K − N_K is, that is when the largest
// eigenvalue of N_K relative to A_K (off A_K's six rigid modes, where both vanish) is below
// 1. This is the computable trace-inequality bound of Shahbazi (J. Comput. Phys. 205,
// 2005) and Epshteyn & Rivière (J. Comput. Appl. Math. 206, 2007), taken per cell from the
// exact matrices instead of a formula. It is sufficient, not necessary: when it fails the
// factorisation still decides, so the penalty a run reaches is the same with or without it.
#include "dg/dg_linear_system.hpp"

namespace altfem::dg {

struct DefinitenessCertificate {
  bool certified = false;  ///< every cell's A_K − N_K positive definite (with a margin of 1e-8)
  /// The largest eigenvalue of N_K relative to A_K over the cells (+∞ for a cell whose stiffness
  /// has more than the six rigid modes in its kernel, or whose penalty has no tangential part).
  double largest_ratio = 0;
  int cells_checked = 0;  ///< distinct (cell class, faces) combinations whose eigenvalue was computed
};

/// The certificate of `system`'s interior-penalty K (flux interior_penalty; degree ≥ 1).
DefinitenessCertificate certify_definiteness(const DgLinearSystem& system);

}  // namespace altfem::dg
