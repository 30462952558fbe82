#pragma once
// The polynomial space each Lagrange element spans on its reference domain,
// as monomials ξ^a η^b ζ^c (one per node, so the nodal basis is unisolvent).
#include <Eigen/Core>
#include <vector>

#include "shared/element/element_type.hpp"

namespace altfem {

/// Exponents (a, b, c) of the monomials spanning the element's space, #nodes of them:
/// tets P_k (total degree ≤ k); Hex8 Q_1 and Hex27 Q_2 (each exponent ≤ 1 or ≤ 2);
/// Hex20 the serendipity space S_2 (superlinear degree ≤ 2: total degree ≤ 2 plus
/// x²y, x²z, y²x, y²z, z²x, z²y, xyz, x²yz, xy²z, xyz²), Arnold & Awanou, "The
/// serendipity family of finite elements", Found. Comput. Math. 11 (2011), §2.
std::vector<Eigen::Vector3i> polynomial_space_exponents(ElementType type);

}  // namespace altfem
