#include "shared/mesh/grid_face_region.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <unordered_map>

#include "shared/common/error.hpp"
#include "shared/geometry/polygon_moments.hpp"

namespace altfem {

namespace {

/// A point's place on the perimeter: side k runs from corner k to corner k+1; within a
/// side, `along` grows in the direction of travel. Exact: a comparison of coordinates.
struct PerimeterPosition {
  int side;
  double along;
  bool operator<(const PerimeterPosition& other) const {
    return side != other.side ? side < other.side : along < other.along;
  }
};

class Perimeter {
public:
  Perimeter(const GridFaceView& face, const std::vector<Eigen::Vector3d>& points) {
    for (int k = 0; k < 4; ++k) {
      const Eigen::Vector3d& start = points[face.corners[k]];
      const Eigen::Vector3d& end = points[face.corners[(k + 1) % 4]];
      Side& side = sides_[k];
      side.varying = start(0) != end(0) ? 0 : start(1) != end(1) ? 1 : 2;
      side.fixed = 3 - face.axis - side.varying;
      side.fixed_value = start(side.fixed);
      side.direction = end(side.varying) > start(side.varying) ? 1.0 : -1.0;
      side.start = start(side.varying);
      side.end = end(side.varying);
    }
  }

  /// The position of `point`, or nothing when it is not on the perimeter. A corner is the
  /// start of the side that leaves it.
  std::optional<PerimeterPosition> position(const Eigen::Vector3d& point) const {
    for (int k = 0; k < 4; ++k) {
      const Side& side = sides_[k];
      if (point(side.fixed) != side.fixed_value) continue;
      const double along = side.direction * point(side.varying);
      if (along >= side.direction * side.start && along < side.direction * side.end) return PerimeterPosition{k, along};
    }
    return std::nullopt;
  }
  PerimeterPosition corner_position(int k) const { return {k, sides_[k].direction * sides_[k].start}; }

private:
  struct Side {
    int varying, fixed;
    double fixed_value, direction, start, end;
  };
  std::array<Side, 4> sides_;
};

double signed_area(const std::vector<int>& loop, const std::vector<Eigen::Vector3d>& points, int axis) {
  Eigen::MatrixXd polygon(loop.size(), 3);
  for (std::size_t i = 0; i < loop.size(); ++i) polygon.row(i) = points[loop[i]];
  return polygon_area_vector(polygon)(axis);
}

}  // namespace

GridFaceRegion grid_face_region(const GridFaceView& face, const std::vector<std::array<int, 2>>& segments,
                                const std::vector<Eigen::Vector3d>& points) {
  GridFaceRegion region;
  if (segments.empty()) {
    region.undetermined = true;
    return region;
  }
  // Chains: follow each segment to the one leaving its end node.
  std::unordered_map<int, int> leaving, arriving;
  for (std::size_t s = 0; s < segments.size(); ++s) {
    if (!leaving.emplace(segments[s][0], static_cast<int>(s)).second ||
        !arriving.emplace(segments[s][1], static_cast<int>(s)).second)
      throw NumericalError("slicing: " + face.name +
                           ": the surface touches itself on this face (non-manifold crossing)");
  }
  std::vector<bool> used(segments.size(), false);
  auto follow = [&](int first) {
    std::vector<int> nodes{segments[first][0]};
    for (int s = first; s >= 0 && !used[s];) {
      used[s] = true;
      nodes.push_back(segments[s][1]);
      const auto next = leaving.find(segments[s][1]);
      s = next == leaving.end() ? -1 : next->second;
    }
    return nodes;
  };
  std::vector<std::vector<int>> chains;  // open: the last node ends the chain
  for (std::size_t s = 0; s < segments.size(); ++s)
    if (!arriving.count(segments[s][0])) chains.push_back(follow(static_cast<int>(s)));
  std::vector<std::vector<int>> closed;
  for (std::size_t s = 0; s < segments.size(); ++s)
    if (!used[s]) {
      closed.push_back(follow(static_cast<int>(s)));
      closed.back().pop_back();  // the first node, repeated
    }

  // Close the open chains along the perimeter, counter-clockwise.
  const Perimeter perimeter(face, points);
  struct Endpoint {
    PerimeterPosition position;
    int chain;
    bool is_start;
  };
  std::vector<Endpoint> endpoints;
  for (std::size_t c = 0; c < chains.size(); ++c)
    for (bool is_start : {true, false}) {
      const auto position = perimeter.position(points[is_start ? chains[c].front() : chains[c].back()]);
      if (!position) throw NumericalError("slicing: " + face.name + ": a surface crossing ends inside the face");
      endpoints.push_back({*position, static_cast<int>(c), is_start});
    }
  std::sort(endpoints.begin(), endpoints.end(),
            [](const Endpoint& a, const Endpoint& b) { return a.position < b.position; });
  std::vector<int> end_slot(chains.size());
  for (std::size_t e = 0; e < endpoints.size(); ++e)
    if (!endpoints[e].is_start) end_slot[endpoints[e].chain] = static_cast<int>(e);
  std::vector<bool> chain_done(chains.size(), false);
  for (std::size_t first = 0; first < chains.size(); ++first) {
    if (chain_done[first]) continue;
    std::vector<int> loop;
    for (int chain = static_cast<int>(first); !chain_done[chain];) {
      chain_done[chain] = true;
      loop.insert(loop.end(), chains[chain].begin(), chains[chain].end());
      const int end = end_slot[chain];
      const Endpoint& next = endpoints[(end + 1) % endpoints.size()];
      if (!next.is_start) throw NumericalError("slicing: " + face.name + ": surface crossings do not alternate");
      // The corners strictly between this chain's end and the next chain's start.
      const PerimeterPosition from = endpoints[end].position, to = next.position;
      const bool wraps = !(from < to);
      for (int step = 1; step <= 4; ++step) {
        const int k = (from.side + step) % 4;
        const PerimeterPosition corner = perimeter.corner_position(k);
        const bool between = wraps ? (from < corner || corner < to) : (from < corner && corner < to);
        if (!between) continue;
        if (!wraps && to < corner) break;
        loop.push_back(face.corners[k]);
      }
      chain = next.chain;
    }
    region.loops.push_back(std::move(loop));
  }

  // Closed crossings inside the face: islands (turning like the face) are loops of their
  // own, holes lie in a loop; a face crossed only by holes is inside around them.
  const double face_turn = signed_area({face.corners.begin(), face.corners.end()}, points, face.axis);
  for (auto& loop : closed)
    (signed_area(loop, points, face.axis) * face_turn > 0 ? region.loops : region.holes).push_back(loop);
  if (region.loops.empty() && !region.holes.empty()) region.loops.push_back({face.corners.begin(), face.corners.end()});
  return region;
}

}  // namespace altfem
