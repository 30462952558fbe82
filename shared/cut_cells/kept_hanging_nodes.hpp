#pragma once
// The hanging nodes of a refined background grid (hexahedral_forest.hpp) among the finite
// cells kept: the kept nodes renumbered free first, and each kept hanging node constrained
// to the kept copies of its masters, so the kept cells' space stays conforming across a
// face between cells of different levels.
#include <vector>

#include "shared/mesh/hexahedral_forest.hpp"
#include "shared/mesh/node_constraints.hpp"

namespace altfem {

struct KeptHangingNodes {
  std::vector<int> new_index;   ///< per kept node: its index in the renumbering, free nodes first
  NodeConstraints constraints;  ///< over the renumbered kept nodes
};

/// `background_node` (#kept nodes): the grid node each kept node is (or copies, with
/// topology-aware cells); the grid's nodes from `grid_free_nodes` on hang, from `sources`;
/// `kept_leaf` (#grid cells): whether a kept cell lies in the grid cell. A kept node of a
/// hanging grid node hangs on the kept copies of the nodes of the first (coarsest) leaf it
/// hangs on that holds a kept cell, substituted until every master is free; it is free
/// where no such leaf holds one, since there is nothing to conform to. Throws NumericalError where a master has several
/// kept copies (the material splits at the refinement's edge, and which copy continues it is not decided).
KeptHangingNodes kept_hanging_nodes(const std::vector<int>& background_node, int grid_free_nodes,
                                    const HangingNodeSources& sources, const std::vector<char>& kept_leaf);

}  // namespace altfem
