#pragma once
// The nodes of each Lagrange element on its reference domain, in VTK's order
// (docs/conventions.md, "Numerical conventions"). Tets live on the UNIT tet with vertices (0,0,0),
// (1,0,0), (0,1,0), (0,0,1); hexes on [-1,1]^3.
#include <Eigen/Core>

#include "shared/element/element_type.hpp"

namespace altfem {

/// Reference coordinates of the element's nodes: #nodes × 3, row i = node i in
/// VTK order (see reference_nodes.cpp for each type's order and its source).
Eigen::MatrixXd reference_nodes(ElementType type);

}  // namespace altfem
