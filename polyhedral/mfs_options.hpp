#pragma once
// The sampling of the method of fundamental solutions (Martin et al. 2008 §5).

namespace altfem::harmonic {

struct MfsOptions {
  /// Kernel centres per edge of a box besides its end nodes (the paper: about 3-5). The
  /// spacing this gives a box of the element's surface area is used everywhere: edges get
  /// as many samples as their length holds (a cut cell's short edges none), faces a grid
  /// of the same spacing. 4, from accuracy against time (docs/performance.md, "The default of 4 samples per edge"): the
  /// solution a user gets does not see the sampling — the sliced bending prism's L2 and H1
  /// errors at 3-6 samples agree within 0.2% (verify_manufactured), the whole bunny's
  /// surface RMS against a fine reference within 1.7% (bench/harmonic_versus_fem.py
  /// --samples) — while the basis costs 0.6-1.1 ms per element at 4 and 1.3-2.0 ms at 5
  /// (bench_polyhedral_element). What 4 gives up against 5 is in the bases themselves:
  /// N_i(x_j) off δ_ij by 0.19 instead of 0.13 at the L-prism's re-entrant edge
  /// (unit_harmonic; 0.25 at 3), the C0 mismatch between the bunny's cut cells 11%
  /// instead of 9.5% (verify_harmonic_continuity; 13% at 3), the trilinear basis of a box
  /// to 6.6e-4 instead of 3.1e-4 (verify_harmonic); below 4 these degrade fastest.
  int edge_samples = 4;
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
