#pragma once
// Recombination of a positive discrete measure (Litterer & Lyons 2012, "High order
// recombination and an application to cubature on Wiener space"; Tchernychova 2016,
// "Carathéodory cubature measures", DPhil thesis, Oxford): keep Σ_j w_j a_j for feature
// columns a_j (here the moment basis at the points) with new weights w ≥ 0 on a small
// subset of the points. Carathéodory–Steinitz elimination removes one point per null
// vector of the columns; applied to all N points at once it costs O(N³). Recombination
// applies it to 2r group sums instead (each group's Σ w_j a_j as one column, weight 1),
// which halves the points per round at O(n r + r³): O(N r + r³ log(N/r)) in all, about
// one pass over the columns. Quadrature simplification's default (Longva et al. 2020,
// §4.4; issue #16's "LP-free pruning"): a cell's thousands of points down to at most M.
#include <Eigen/Core>

namespace altfem {

/// columns: r × N, weights: N (>= 0). New weights (N, >= 0) with at most
/// max(target_size, rank) non-zeros, each a subset of the input's, and
/// columns · result = columns · weights up to rounding (relative ≈ 1e-15 per round).
/// Stops early, above target_size, when the group sums are linearly independent.
Eigen::VectorXd caratheodory_recombination(const Eigen::Ref<const Eigen::MatrixXd>& columns,
                                           const Eigen::Ref<const Eigen::VectorXd>& weights, Eigen::Index target_size);

}  // namespace altfem
