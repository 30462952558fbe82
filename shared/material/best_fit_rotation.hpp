#pragma once
// The rotation of an element's deformation for corotated ("stiffness warping")
// schemes: fit an affine map to the deformation in the least-squares sense and take
// the rotational factor of its linear part by polar decomposition (Kaufmann et al.
// 2009 §6.1, after Hauth & Strasser 2004; the same fit is Müller et al. 2005's shape
// matching, which Martin et al. 2008 §6 use for harmonic elements).
#include <Eigen/Core>

namespace altfem {

/// R of F = R S (S symmetric positive semi-definite), a proper rotation (det +1) even
/// for det F ≤ 0 (the rotation-variant SVD of polar_decomposition.hpp).
Eigen::Matrix3d polar_rotation(const Eigen::Matrix3d& F);

/// The rotation of the weighted least-squares affine map x ≈ A X + b between point sets:
/// rest, deformed: #points × 3 (≥ 4 points not all coplanar), weights: #points, > 0.
/// A = (Σ w q̂ p̂ᵀ)(Σ w p̂ p̂ᵀ)⁻¹ with p̂, q̂ the points relative to their weighted
/// centroids; returns polar_rotation(A).
Eigen::Matrix3d best_fit_rotation(const Eigen::MatrixXd& rest, const Eigen::MatrixXd& deformed,
                                  const Eigen::VectorXd& weights);

}  // namespace altfem
