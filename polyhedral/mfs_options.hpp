#pragma once
// The sampling of the method of fundamental solutions (Martin et al. 2008 §5).

namespace altfem::harmonic {

struct MfsOptions {
  /// Kernel centres per edge of a box besides its end nodes (the paper: about 3-5). The
  /// spacing this gives a box of the element's surface area is used everywhere: edges get
  /// as many samples as their length holds (a cut cell's short edges none), faces a grid
  /// of the same spacing. 5: on a non-convex L-prism 3 leave N_i(x_j) off δ_ij by 0.25 at
  /// the re-entrant edge, 5 by 0.13, 10 by 0.075 (unit_harmonic); on boxes 4 already give
  /// the trilinear basis to 7e-4 at half the cost (verify_harmonic, bench_polyhedral_element).
  int edge_samples = 5;
  /// Collocation points per kernel centre (m ≈ 3n, eq. (13)): a denser sampling of
  /// the same kind.
  int collocation_factor = 3;
  /// ξ of eq. (12): centres move outward by ξ · size(e) (the element's diameter) along
  /// the interpolated normal. The paper uses 0.1. On box cells the MFS basis approaches
  /// the trilinear one faster the farther the centres (verify_harmonic prints the table;
  /// 4 edge samples: ξ = 0.1 misses it by 5.8e-3, 0.2 by 8.8e-4, 0.3 by 2.0e-4, 0.5 by
  /// 1.5e-5), but far centres fit the kinks of non-convex cells' boundary data worse;
  /// 0.2 is kept until the non-convex cells are measured the same way.
  double offset = 0.2;
};

}  // namespace altfem::harmonic
