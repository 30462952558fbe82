#pragma once
#include "shared/assembly/tabulated_elements.hpp"
#include "shared/mesh/node_constraints.hpp"

namespace altfem {

/// Elements tabulated over a mesh's nodes (basis function i is node i) with each hanging
/// node's function handed to its masters: an element's basis becomes its free nodes and the
/// masters of its hanging ones, N'_m = N_m + Σ_h w_hm N_h, values and gradients alike (the
/// constrained space of hanging nodes, u = C ū). An element without hanging nodes is
/// copied bit for bit.
TabulatedElements constrain_lagrange_elements(const TabulatedElements& elements, const NodeConstraints& constraints);

}  // namespace altfem
