#pragma once
#include "shared/assembly/tabulated_elements.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem {

/// Tabulates a conforming Lagrange mesh: for each cell, the reference rule of
/// `quadrature_strength` (tet_rule / hex_rule), weights w_q |det J(ξ_q)|, basis values,
/// and physical gradients ∇N = (∂N/∂ξ) J⁻¹. Basis function i is mesh node i.
/// OpenMP-parallel over cells. Throws NumericalError naming the cell and point when
/// det J ≤ 0 (an inverted or degenerate cell).
TabulatedElements tabulate_lagrange(const VolumeMesh& mesh, int quadrature_strength);

}  // namespace altfem
