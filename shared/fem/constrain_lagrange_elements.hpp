#pragma once
#include <span>
#include <vector>

#include "shared/assembly/element_masses.hpp"
#include "shared/assembly/tabulated_elements.hpp"
#include "shared/mesh/node_constraints.hpp"

namespace altfem {

/// Whether any of a cell's nodes hangs (is not among the constraints' free nodes).
bool any_hanging(std::span<const int> nodes, const NodeConstraints& constraints);
/// The functions of a cell's nodes `nodes` (some hanging) in the constrained space: `basis`
/// its free nodes and the masters of its hanging ones, `substitution` (#nodes × #basis)
/// column j the function basis[j] in the nodes' functions. Both are rewritten.
void substitute_hanging(std::span<const int> nodes, const NodeConstraints& constraints, std::vector<int>& basis,
                        Eigen::MatrixXd& substitution);

/// Element masses reduced over the cells `cells` (#cells × nodes per cell: element e's
/// basis is row e) in the same constrained basis, in the order substitute_hanging gives
/// it (tabulate_lagrange's): Sᵀ M S and Sᵀ m for an element whose nodes hang (S its substitution), the
/// others unchanged.
ElementMasses constrain_element_masses(const ElementMasses& masses, const Eigen::MatrixXi& cells,
                                       const NodeConstraints& constraints);

}  // namespace altfem
