#pragma once
#include "shared/assembly/element_masses.hpp"
#include "shared/assembly/tabulated_elements.hpp"
#include "shared/mesh/node_constraints.hpp"

namespace altfem {

/// Elements tabulated over a mesh's nodes (basis function i is node i) with each hanging
/// node's function handed to its masters: an element's basis becomes its free nodes and the
/// masters of its hanging ones, N'_m = N_m + Σ_h w_hm N_h, values and gradients alike (the
/// constrained space of hanging nodes, u = C ū). An element without hanging nodes is
/// copied bit for bit; one held elsewhere (a rank's share) stays so, with its basis in the
/// constrained space.
TabulatedElements constrain_lagrange_elements(const TabulatedElements& elements, const NodeConstraints& constraints);

/// Element masses reduced over the cells `cells` (#cells × nodes per cell: element e's
/// basis is row e) in the same constrained basis, in the order constrain_lagrange_elements
/// gives it: Sᵀ M S and Sᵀ m for an element whose nodes hang (S its substitution), the
/// others unchanged.
ElementMasses constrain_element_masses(const ElementMasses& masses, const Eigen::MatrixXi& cells,
                                       const NodeConstraints& constraints);

}  // namespace altfem
