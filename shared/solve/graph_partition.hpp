#pragma once
// METIS's k-way partition of a graph, the same on every rank (docs/scaling.md): which
// rank assembles which element (element_partition.hpp, dg/cell_partition.hpp) and which
// rows of a distributed matrix each rank holds (partitioned_rows.hpp).
#include <functional>
#include <vector>

namespace altfem {

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
