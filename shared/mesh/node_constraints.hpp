#pragma once
// Hanging nodes of a Lagrange mesh as linear constraints (deal.II's AffineConstraints idea):
// the first `free_nodes` nodes carry the basis functions (DOFs); every later node's values
// are a fixed combination of free nodes' — the coarser neighbour's interpolation at it — so
// the space stays conforming across a face between cells of different levels.
#include <Eigen/Core>
#include <utility>
#include <vector>

namespace altfem {

struct NodeConstraints {
  int free_nodes = 0;  ///< nodes 0 .. free_nodes − 1 are basis functions
  /// Node free_nodes + i = Σ_k weights[i][k] · node masters[i][k]; every master is free.
  std::vector<std::vector<int>> masters;
  std::vector<std::vector<double>> weights;

  bool empty() const { return masters.empty(); }
  int hanging_nodes() const { return static_cast<int>(masters.size()); }

  /// A node list with values (a cell's nodes and their shape values at a point) with every
  /// hanging node replaced by its masters, weights × value; masters met twice are summed.
  /// basis and values are rewritten in place.
  void substitute(std::vector<int>& basis, std::vector<double>& values) const;
  /// The values at every node (3 per node, #nodes = free_nodes + hanging_nodes()) of
  /// coefficients u of the free nodes (3 × free_nodes).
  Eigen::VectorXd all_nodes(const Eigen::VectorXd& u) const;
};

/// Per node, the combination of other nodes that gives its values (masters, weights); empty
/// for a free node. A master may be constrained itself (a chain, which 2:1 balance keeps
/// one level per step); chains must end in free nodes.
using DirectConstraints = std::vector<std::vector<std::pair<int, double>>>;

/// `direct`'s nodes renumbered free first, then the constrained ones, each in their order
/// (`new_index`, #nodes: a node's index in the renumbering), and the constraints over the
/// renumbered nodes with every chain substituted down to free masters.
NodeConstraints resolve_constraints(const DirectConstraints& direct, std::vector<int>& new_index);

}  // namespace altfem
