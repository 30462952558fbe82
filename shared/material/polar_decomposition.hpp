#pragma once
// Polar decomposition F = R S through the rotation-variant SVD, and the
// derivative of R, for the corotated model.
#include <Eigen/Core>

#include "shared/material/material.hpp"

namespace altfem {

/// F = U diag(sigma) Vᵀ with U, V proper rotations (det +1). sigma is sorted
/// sigma0 ≥ sigma1 ≥ |sigma2|; sigma2 < 0 exactly when det F < 0 (Irving, Teran
/// & Fedkiw 2004, "Invertible Finite Elements"), so R = U Vᵀ is always a rotation.
struct RotationVariantSvd {
  Eigen::Matrix3d U;
  Eigen::Vector3d sigma;
  Eigen::Matrix3d V;
};

RotationVariantSvd rotation_variant_svd(const Eigen::Matrix3d& F);

/// ∂vec(R)/∂vec(F) (9 × 9, Matrix9d's ordering) for R = U Vᵀ: the twist
/// eigen-system of Smith, De Goes & Kim 2019, "Analytic Eigensystems for
/// Isotropic Distortion Energies" (the twist modes):
///   Σ over pairs a < b of  2/(σa + σb) · vec(T_ab) vec(T_ab)ᵀ,
///   T_ab = (u_a v_bᵀ − u_b v_aᵀ)/√2.
/// Only the sums σa + σb appear, so repeated singular values are harmless. Where
/// σa + σb → 0 (a flat or inverted element) R is discontinuous and the
/// derivative unbounded; the sum is clamped below at ε · max(σ0, 1) so the
/// result stays finite.
Matrix9d polar_rotation_derivative(const RotationVariantSvd& svd);

}  // namespace altfem
