#include "shared/solve/graph_partition.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "shared/solve/process_ranks.hpp"

#ifdef ALTFEM_HAVE_METIS
#include <metis.h>
#endif

namespace altfem {
namespace {

#ifdef ALTFEM_HAVE_METIS

// Whether every vertex is reached from the first through the graph's edges.
bool connected(const PartitionGraph& graph, idx_t vertices) {
  if (vertices == 0) return true;
  std::vector<char> reached(static_cast<size_t>(vertices), 0);
  std::vector<int> stack{0};
  reached[0] = 1;
  idx_t count = 1;
  while (!stack.empty()) {
    const int vertex = stack.back();
    stack.pop_back();
    for (long long k = graph.offsets[vertex]; k < graph.offsets[vertex + 1]; ++k)
      if (const int next = graph.neighbours[k]; !reached[next]) reached[next] = 1, ++count, stack.push_back(next);
  }
  return count == vertices;
}

std::vector<int> metis_parts(const PartitionGraph& graph, const std::vector<double>& work, int parts) {
  idx_t vertices = static_cast<idx_t>(work.size()), constraints = 1, part_count = parts, cut = 0;
  std::vector<idx_t> offsets(graph.offsets.begin(), graph.offsets.end());
  std::vector<idx_t> neighbours(graph.neighbours.begin(), graph.neighbours.end());
  double total = 0;
  for (const double w : work) total += w;
  // METIS sums the weights in idx_t: scaled so that the total stays below 2^30.
  const double scale = std::min(1.0, 0x1p30 / std::max(total, 1.0));
  std::vector<idx_t> weights(static_cast<size_t>(vertices));
  for (idx_t e = 0; e < vertices; ++e) weights[e] = std::max<idx_t>(1, static_cast<idx_t>(scale * work[e]));
  std::vector<idx_t> part(static_cast<size_t>(vertices), 0);
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = 1;
  // Contiguous parts need a connected graph: a body a cut has separated is not one (METIS
  // would refuse it, printing an error).
  options[METIS_OPTION_CONTIG] = connected(graph, vertices) ? 1 : 0;
  const int status = METIS_PartGraphKway(&vertices, &constraints, offsets.data(), neighbours.data(), weights.data(),
                                         nullptr, nullptr, &part_count, nullptr, nullptr, options, &cut, part.data());
  if (status != METIS_OK)
    throw std::runtime_error("METIS could not partition " + std::to_string(vertices) + " vertices into " +
                             std::to_string(parts) + " parts (status " + std::to_string(status) + ")");
  return {part.begin(), part.end()};
}

#else

std::vector<int> metis_parts(const PartitionGraph&, const std::vector<double>&, int) {
  throw std::logic_error("partition_graph: this build has no METIS (it comes with -DALTFEM_PETSC=ON)");
}

#endif

}  // namespace

PartitionGraph compressed_graph(std::vector<std::vector<int>> adjacent) {
  PartitionGraph graph;
  graph.offsets.reserve(adjacent.size() + 1);
  graph.offsets.push_back(0);
  for (std::vector<int>& list : adjacent) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    graph.neighbours.insert(graph.neighbours.end(), list.begin(), list.end());
    graph.offsets.push_back(static_cast<long long>(graph.neighbours.size()));
  }
  return graph;
}

std::vector<int> partition_graph(const std::function<PartitionGraph()>& graph, const std::vector<double>& work,
                                 int parts) {
  const int vertices = static_cast<int>(work.size());
  std::vector<int> part(static_cast<size_t>(vertices), 0);
  if (parts <= 1 || vertices == 0) return part;
  if (vertices <= parts) {
    for (int e = 0; e < vertices; ++e) part[e] = e;
    return part;
  }
  ranks::collectively([&] {
    if (ranks::index() == 0) part = metis_parts(graph(), work, parts);
  });
  ranks::broadcast(part);
  return part;
}

}  // namespace altfem
