#include "shared/mesh/planar_loops.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "shared/common/error.hpp"

namespace altfem {
namespace {

// Whether `point` of the polygon's plane lies inside it: the crossing number of the
// polygon projected along the axis its normal is largest in. Only asked of midpoints of
// stretches no edge crosses, so rounding cannot flip it but for slivers the caller refuses.
bool inside_polygon(const Eigen::Vector3d& point, const std::vector<int>& loop,
                    const std::vector<Eigen::Vector3d>& positions, const Eigen::Vector3d& normal) {
  Eigen::Index dropped = 0;
  normal.cwiseAbs().maxCoeff(&dropped);
  const int u = static_cast<int>((dropped + 1) % 3), v = static_cast<int>((dropped + 2) % 3);
  bool inside = false;
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const Eigen::Vector3d& p = positions[loop[k]];
    const Eigen::Vector3d& q = positions[loop[(k + 1) % loop.size()]];
    if ((p[v] > point[v]) == (q[v] > point[v])) continue;
    const double crossing = p[u] + (point[v] - p[v]) / (q[v] - p[v]) * (q[u] - p[u]);
    if (crossing > point[u]) inside = !inside;
  }
  return inside;
}

}  // namespace

Eigen::Vector3d loop_area_vector(const std::vector<int>& loop, const std::vector<Eigen::Vector3d>& positions) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < loop.size(); ++k) sum += positions[loop[k]].cross(positions[loop[(k + 1) % loop.size()]]);
  return sum / 2;
}

std::vector<std::vector<int>> trace_planar_loops(const std::vector<std::pair<int, int>>& edges,
                                                 const std::vector<Eigen::Vector3d>& positions,
                                                 const Eigen::Vector3d& normal) {
  std::multimap<int, std::size_t> leaving;  // node → index into edges
  for (std::size_t e = 0; e < edges.size(); ++e) leaving.emplace(edges[e].first, e);
  std::vector<bool> used(edges.size(), false);
  // The edge leaving the end of `arriving` that turns furthest left about `normal`.
  const auto next_edge = [&](std::size_t arriving) {
    const auto [from, node] = edges[arriving];
    const Eigen::Vector3d incoming = positions[node] - positions[from];
    std::size_t best = edges.size();
    double best_turn = -10;
    for (auto [it, end] = leaving.equal_range(node); it != end; ++it) {
      const Eigen::Vector3d outgoing = positions[edges[it->second].second] - positions[node];
      const double turn = std::atan2(normal.dot(incoming.cross(outgoing)), incoming.dot(outgoing));
      if (turn > best_turn) std::tie(best, best_turn) = std::pair{it->second, turn};
    }
    return best;
  };
  std::vector<std::vector<int>> loops;
  for (std::size_t first = 0; first < edges.size(); ++first) {
    if (used[first]) continue;
    std::vector<int> loop;
    for (std::size_t edge = first;;) {
      used[edge] = true;
      loop.push_back(edges[edge].first);
      edge = next_edge(edge);
      if (edge == first) break;
      if (edge == edges.size() || used[edge])
        throw NumericalError("the edges through node " + std::to_string(loop.back()) + " do not close into loops");
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

std::vector<PolygonPiece> split_polygon_by_plane(const std::vector<int>& loop,
                                                 const std::vector<Eigen::Vector3d>& positions,
                                                 const std::vector<int>& side, const Eigen::Vector3d& plane_normal) {
  const Eigen::Vector3d normal = loop_area_vector(loop, positions);
  // Along the line where the plane meets the polygon's plane: its left (normal × line) is
  // the plane's negative side, so a stretch of the line inside the polygon is an edge of
  // the negative pieces run along `line` and of the positive ones run against it.
  const Eigen::Vector3d line = normal.cross(plane_normal);
  std::vector<std::pair<double, int>> on_line;  // (position along the line, place in loop)
  for (std::size_t k = 0; k < loop.size(); ++k)
    if (side[loop[k]] == 0) on_line.emplace_back(positions[loop[k]].dot(line), static_cast<int>(k));
  std::sort(on_line.begin(), on_line.end());
  std::vector<std::pair<int, int>> edges_of_side[2];  // [0]: positive, [1]: negative
  const auto add = [&](int sigma, int from, int to) { edges_of_side[sigma > 0 ? 0 : 1].emplace_back(from, to); };
  const int count = static_cast<int>(loop.size());
  for (int k = 0; k < count; ++k) {
    const int from = loop[k], to = loop[(k + 1) % count];
    if (side[from] != 0 || side[to] != 0) {
      add(side[from] != 0 ? side[from] : side[to], from, to);
      continue;
    }
    const double along = (positions[to] - positions[from]).dot(line);
    if (along == 0) throw NumericalError("the polygon has two nodes on the cutting plane too close to order");
    add(along > 0 ? -1 : +1, from, to);
  }
  for (std::size_t i = 0; i + 1 < on_line.size(); ++i) {
    const int k = on_line[i].second, l = on_line[i + 1].second;
    if ((k + 1) % count == l || (l + 1) % count == k) continue;  // an edge of the polygon
    const int from = loop[k], to = loop[l];
    if (!inside_polygon((positions[from] + positions[to]) / 2, loop, positions, normal)) continue;
    add(-1, from, to);
    add(+1, to, from);
  }
  std::vector<PolygonPiece> pieces;
  for (const int sigma : {+1, -1})
    for (std::vector<int>& piece : trace_planar_loops(edges_of_side[sigma > 0 ? 0 : 1], positions, normal))
      pieces.push_back({std::move(piece), sigma});
  return pieces;
}

}  // namespace altfem
