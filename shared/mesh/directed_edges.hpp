#pragma once
// The edges of a triangle list, each use of an edge by a face as one directed edge, sorted so
// that an edge's uses either way are one run: how split_surface_by_plane pairs the faces of a
// side across their edges, where a section touching itself gives an edge more than two faces.
#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace altfem {

/// A face's edge from its corner `corner` (point `from`) to the next (point `to`).
struct DirectedEdge {
  int from, to, face, corner;
  // By the edge its points make, then its direction, then the face: the uses of one edge
  // either way are one run, those from its lower point first. As two keys, for the sort.
  std::uint64_t edge, order;
  DirectedEdge(int from_point, int to_point, int face_index, int corner_index)
      : from(from_point),
        to(to_point),
        face(face_index),
        corner(corner_index),
        edge(static_cast<std::uint64_t>(std::min(from, to)) << 32 | static_cast<std::uint32_t>(std::max(from, to))),
        order(static_cast<std::uint64_t>(from > to) << 62 | static_cast<std::uint64_t>(face) << 2 |
              static_cast<std::uint64_t>(corner)) {}
  int low() const { return std::min(from, to); }
  int high() const { return std::max(from, to); }
  bool operator<(const DirectedEdge& other) const {
    return edge != other.edge ? edge < other.edge : order < other.order;
  }
};

/// Every face's edges (faces: #faces point triples), sorted as DirectedEdge orders them.
std::vector<DirectedEdge> directed_edges(const std::vector<std::array<int, 3>>& faces);

/// Calls visit(a, b, forward, backward) for each edge of points a < b: its uses from a to b
/// and from b to a, each a pair of iterators.
template <class Visit>
bool for_each_edge(const std::vector<DirectedEdge>& edges, const Visit& visit) {
  using Uses = std::pair<std::vector<DirectedEdge>::const_iterator, std::vector<DirectedEdge>::const_iterator>;
  for (auto first = edges.begin(); first != edges.end();) {
    const int a = first->low(), b = first->high();
    auto middle = first;
    while (middle != edges.end() && middle->edge == first->edge && middle->from == a) ++middle;
    auto last = middle;
    while (last != edges.end() && last->edge == first->edge) ++last;
    if (!visit(a, b, Uses{first, middle}, Uses{middle, last})) return false;
    first = last;
  }
  return true;
}

}  // namespace altfem
