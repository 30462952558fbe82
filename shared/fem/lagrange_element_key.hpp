#pragma once
// What the embedding after an event compares to keep a point of a Lagrange cell
// (ElementBasisEvaluator::element_key): a cell's basis at a point is its inverse map and
// shape functions, read from its type and its nodes' positions, with every hanging
// node's value handed to its masters (NodeConstraints::substitute), whose order in the
// list follows from which of the cell's nodes and masters are the same function.
#include <cstdint>
#include <vector>

#include "shared/mesh/node_constraints.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem {

/// A 64-bit hash of the cell's type, its nodes' positions in order, and the substitution
/// of its hanging nodes (constraints may be null: none) with each function named by its
/// first place in the cell's node list followed by the masters' lists, not by its number.
std::uint64_t lagrange_element_key(const VolumeMesh& mesh, const NodeConstraints* constraints, int cell);

/// The functions the cell's basis lists at any point, in their order: its nodes with
/// every hanging node replaced by its masters (NodeConstraints::substitute).
void lagrange_element_functions(const VolumeMesh& mesh, const NodeConstraints* constraints, int cell,
                                std::vector<int>& functions);

}  // namespace altfem
