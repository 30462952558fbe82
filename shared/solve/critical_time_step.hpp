#pragma once
#include "shared/solve/discretization.hpp"

namespace altfem {

/// The stability limit of explicit (symplectic) Euler, h_crit = 2 / ω_max, with ω_max²
/// the largest eigenvalue of M_e⁻¹ K at rest over the free DOFs (M_e the method's
/// explicit mass), estimated by power iteration. The power iteration approaches
/// ω_max² from below, so the estimate errs on the large side by a few per cent: a step
/// above it certainly diverges. One Hessian assembly plus `iterations` products.
double estimate_critical_time_step(const Discretization& discretization, int iterations = 50);

}  // namespace altfem
