#pragma once
// The element masses (ElementMasses) of a Lagrange mesh straight from its cells'
// rules, without tabulating gradients: what a method needs of rules that serve only
// the mass matrix and the loads, once (the FCM's cut-cell mass rules, Longva et al.
// 2020 §6, run to millions of points).
#include "shared/assembly/element_masses.hpp"
#include "shared/fem/tabulate_lagrange.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem {

/// One entry per cell of `mesh`, in order: Σ_q w_q |det J(ξ_q)| N_a(ξ_q) N_b(ξ_q) and
/// Σ_q w_q |det J| N_a(ξ_q) over the cell's rule (`rules.custom`, else `rules.standard`).
/// OpenMP-parallel over cells. Throws NumericalError naming the cell where det J ≤ 0.
ElementMasses lagrange_element_masses(const VolumeMesh& mesh, const LagrangeCellRules& rules);

}  // namespace altfem
