#include "shared/mesh/directed_edges.hpp"

namespace altfem {

// Placed by their lower point (a counting sort, linear in the edges), then each point's few
// sorted in place.
std::vector<DirectedEdge> directed_edges(const std::vector<std::array<int, 3>>& faces) {
  int points = 0;
  for (const std::array<int, 3>& face : faces) points = std::max({points, face[0] + 1, face[1] + 1, face[2] + 1});
  std::vector<int> start(static_cast<std::size_t>(points) + 1, 0);
  for (const std::array<int, 3>& face : faces)
    for (int k = 0; k < 3; ++k) ++start[std::min(face[k], face[(k + 1) % 3]) + 1];
  for (int point = 0; point < points; ++point) start[point + 1] += start[point];
  std::vector<DirectedEdge> edges(3 * faces.size(), DirectedEdge(0, 0, 0, 0));
  std::vector<int> next(start.begin(), start.end() - 1);
  for (int f = 0; f < static_cast<int>(faces.size()); ++f)
    for (int k = 0; k < 3; ++k) {
      const DirectedEdge edge(faces[f][k], faces[f][(k + 1) % 3], f, k);
      edges[next[edge.low()]++] = edge;
    }
  for (int point = 0; point < points; ++point)
    std::sort(edges.begin() + start[point], edges.begin() + start[point + 1]);
  return edges;
}

}  // namespace altfem
