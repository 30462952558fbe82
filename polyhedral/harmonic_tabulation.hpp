#pragma once
// One harmonic element tabulated for the shared assembler (TabulatedElements::add):
// its basis at the points of a rule on the cell.
//
// Consistency under quadrature (beyond Martin et al. 2008, who integrate by bounding-box
// subdivision or Monte Carlo): the quadrature of ∇N_i over the element differs from the
// exact ∫_∂e b_i n dA of the boundary data b_i that neighbours share, so a constant
// stress leaves ghost forces on interior nodes (the patch test fails). The correction
// shifts each gradient by the constant
//   c_i = (∫_∂e b_i n dA − Σ_q w_q ∇N_i(x_q)) / Σ_q w_q,
// after which Σ_q w_q (∇N_i + c_i) = ∫_∂e b_i n dA exactly, the face terms of neighbours
// cancel, and linear fields keep exact gradients (Σ_i x_i ⊗ c_i = 0 when the rule
// integrates constants and the face data reproduce linear functions). PolyFEM's
// integral constraints for its RBF bases serve the same end.
#include <Eigen/Core>

#include "polyhedral/element_harmonic_basis.hpp"
#include "shared/quadrature/polyhedron_rule.hpp"

namespace altfem::harmonic {

struct HarmonicTabulation {
  Eigen::VectorXd weights;    ///< #points
  Eigen::MatrixXd values;     ///< #points × #nodes
  Eigen::MatrixXd gradients;  ///< (#points·#nodes) × 3, point-major
};

HarmonicTabulation tabulate_harmonic_element(const ElementHarmonicBasis& basis, const PolyhedronRule& rule,
                                             bool consistent);

}  // namespace altfem::harmonic
