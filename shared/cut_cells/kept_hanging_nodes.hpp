#pragma once
// The hanging nodes of a refined background grid (hexahedral_forest.hpp) among the finite
// cells kept: the kept nodes renumbered free first, and each kept hanging node constrained
// to the kept copies of its masters, so the kept cells' space stays conforming across a
// face between cells of different levels.
#include <vector>

#include "shared/mesh/node_constraints.hpp"

namespace altfem {

struct KeptHangingNodes {
  std::vector<int> new_index;   ///< per kept node: its index in the renumbering, free nodes first
  NodeConstraints constraints;  ///< over the renumbered kept nodes
};

/// `background_node` (#kept nodes): the background node each kept node is (or copies, with
/// topology-aware cells); `background`: the grid's constraints over its nodes. A kept node
/// of a hanging background node hangs on the kept copies of its masters. It is free where a
/// master has no kept copy: the coarse cell it hangs on holds no kept material, so there is
/// nothing to conform to. Throws NumericalError where a master has several kept copies (the
/// material splits at the refinement's edge, and which copy continues it is not decided).
KeptHangingNodes kept_hanging_nodes(const std::vector<int>& background_node, const NodeConstraints& background);

}  // namespace altfem
