#pragma once
// The hanging nodes of a refined background grid (hexahedral_forest.hpp) among the finite
// cells kept: the kept nodes renumbered free first, and each kept hanging node constrained
// to its source leaf's copies of its masters, so the kept cells' space stays conforming
// across a face between cells of different levels.
#include <Eigen/Core>
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
/// `cells` (#kept cells × nodes per cell): the kept cells' nodes; `cell_leaf` (#kept
/// cells): the grid cell each lies in. A kept node of a hanging grid node hangs on the
/// nodes of the first (coarsest) leaf it hangs on that holds a kept cell, as that leaf's
/// cell holds them: where the material splits at the refinement's edge, a master has a copy
/// per part of the material around it, and the leaf's copy is the one its interpolation
/// reads. Masters are substituted until every one is free; a hanging node is free where no
/// leaf it hangs on holds a kept cell, since there is nothing to conform to. A leaf holding
/// several pieces gives the copies of the one that shares a node with the hanging node's
/// cells (the material continuing across the face); throws NumericalError naming the grid
/// node where not exactly one does.
KeptHangingNodes kept_hanging_nodes(const std::vector<int>& background_node, int grid_free_nodes,
                                    const HangingNodeSources& sources, const Eigen::MatrixXi& cells,
                                    const std::vector<int>& cell_leaf);

}  // namespace altfem
