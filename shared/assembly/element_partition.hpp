#pragma once
// Which rank assembles which element in a run over several processes (docs/scaling.md):
// METIS's k-way partition of the element graph, two elements adjacent when they share a
// basis function or a method's term couples them (a DG face, a ghost-penalty face), each
// weighted by its assembly work, so that the ranks' shares cost about the same and few
// functions are shared across ranks.
#include <functional>
#include <vector>

#include "shared/assembly/basis_groups.hpp"
#include "shared/assembly/tabulated_elements.hpp"

namespace altfem {

/// The part (0 … parts − 1) of each element (#elements), the same on every rank (rank 0's
/// partition, broadcast). Parts are contiguous where the element graph is connected.
/// Throws std::logic_error for parts > 1 in a build without METIS (which comes with PETSc).
std::vector<int> partition_elements(const TabulatedElements& elements, const BasisGroups& couplings, int parts);

/// A graph in compressed adjacency: the neighbours of vertex v are neighbours[offsets[v]
/// … offsets[v + 1]), each edge listed from both ends.
struct PartitionGraph {
  std::vector<long long> offsets;
  std::vector<int> neighbours;
};

/// The compressed form of the graph whose vertex v neighbours the vertices of adjacent[v]
/// (repeats dropped, neighbours sorted; give each edge from both ends).
PartitionGraph compressed_graph(std::vector<std::vector<int>> adjacent);

/// The part of each vertex (#work entries) by METIS's k-way partition of `graph` (built
/// on rank 0 only), each vertex weighted by its `work`; the same on every rank, contiguous
/// where the graph is connected. Throws std::logic_error for parts > 1 without METIS.
std::vector<int> partition_graph(const std::function<PartitionGraph()>& graph, const std::vector<double>& work,
                                 int parts);

}  // namespace altfem
