#pragma once
// Recombination of a positive discrete measure (Litterer & Lyons 2012; Tchernychova
// 2016, "Carathéodory cubature measures", ch. 3): keep Σ_j w_j a_j for feature columns
// a_j (here the moment basis at the points), with new weights w ≥ 0 on a small subset
// of the points. Carathéodory–Steinitz elimination removes one point per null vector of
// the columns; applied to all N points it costs O(N² r). Recombination applies it to
// 2r group sums instead (each group's Σ w_j a_j as one column, weight 1), which halves
// the points per round at O(n r + r³): O(N r + r³ log(N/r)) in all, a single pass over
// the columns. Used by quadrature simplification (Longva et al. 2020, §4.4) to shrink
// a rule of thousands of points to a few times M before the LP or NNLS picks M.
#include <Eigen/Core>

namespace altfem {

/// columns: r × N, weights: N (>= 0). New weights (N, >= 0) with at most
/// max(target_size, rank) non-zeros, each a subset of the input's, and
/// columns · result = columns · weights up to rounding (relative ≈ 1e-15 per round).
/// Stops early, above target_size, when the group sums are linearly independent.
Eigen::VectorXd caratheodory_recombination(const Eigen::Ref<const Eigen::MatrixXd>& columns,
                                           const Eigen::Ref<const Eigen::VectorXd>& weights,
                                           Eigen::Index target_size);

}  // namespace altfem
