#pragma once
// Lamé parameters of an isotropic material from the engineering constants.

namespace altfem {

/// The two Lamé parameters [Pa]: λ (first) and μ (shear modulus).
struct LameParameters {
  double lambda;
  double mu;
};

/// λ = Eν / ((1 + ν)(1 − 2ν)), μ = E / (2(1 + ν)) (any elasticity textbook, e.g.
/// Bonet & Wood, "Nonlinear Continuum Mechanics for Finite Element Analysis").
/// Throws InputError unless E is finite and > 0 and −1 < ν < 1/2.
LameParameters lame_parameters(double youngs_modulus, double poisson_ratio);

}  // namespace altfem
