#pragma once
// The sampling of the method of fundamental solutions (Martin et al. 2008 §5).

namespace altfem::harmonic {

struct MfsOptions {
  /// Kernel centres per edge besides its end nodes (the paper: about 3-5). Faces are
  /// sampled at about the same spacing.
  int edge_samples = 5;
  /// Collocation points per kernel centre (m ≈ 3n, eq. (13)): a denser sampling of
  /// the same kind.
  int collocation_factor = 3;
  /// ξ of eq. (12): centres move outward by ξ · size(e) (the element's diameter) along
  /// the interpolated normal. The paper uses 0.1; measured here (unit tests, harmonic
  /// basis of the unit cube against the trilinear one, 5 edge samples): ξ = 0.1 misses
  /// the trilinear basis by 2.5e-3, ξ = 0.2 by 3.7e-4, and ξ = 0.3 makes the least-squares
  /// system so ill-conditioned that the gradients lose digits.
  double offset = 0.2;
};

}  // namespace altfem::harmonic
