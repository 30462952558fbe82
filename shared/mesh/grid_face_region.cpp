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

namespace altfem {

namespace {

/// The face's in-plane coordinates (u, v) = (x_(axis+1), x_(axis+2)): counter-clockwise
/// about +e_axis is counter-clockwise in (u, v).
Eigen::Vector2d in_plane(const Eigen::Vector3d& point, int axis) {
  return {point((axis + 1) % 3), point((axis + 2) % 3)};
}

bool inside_polygon(const Eigen::Vector2d& point, const std::vector<Eigen::Vector2d>& polygon) {
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[j];
    if ((a.y() > point.y()) != (b.y() > point.y()) &&
        point.x() < a.x() + (point.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
      inside = !inside;
  }
  return inside;
}

/// The outer vertex a bridge from `from` along `direction` (+1: +u, −1: −u) reaches: the
/// nearer end of the first outer edge the ray meets, or the outer vertex inside the
/// triangle (from, hit, that end) closest in angle to the ray (Eberly, "Triangulation by
/// ear clipping", §3). −1 when the ray meets another hole first.
int bridge_target(const Eigen::Vector2d& from, double direction, const std::vector<Eigen::Vector2d>& outer,
                  const std::vector<std::vector<Eigen::Vector2d>>& other_holes) {
  // Work with u mirrored for −u so the ray always runs along +u.
  auto mirrored = [&](Eigen::Vector2d p) { return Eigen::Vector2d(direction * p.x(), p.y()); };
  const Eigen::Vector2d origin = mirrored(from);
  auto ray_hit = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b, double& distance) {
    if ((a.y() > origin.y()) == (b.y() > origin.y())) return false;
    const double u = a.x() + (origin.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
    if (u <= origin.x()) return false;
    distance = u - origin.x();
    return true;
  };
  double nearest = std::numeric_limits<double>::infinity();
  int hit_edge = -1;
  for (std::size_t i = 0; i < outer.size(); ++i) {
    double distance;
    if (ray_hit(mirrored(outer[i]), mirrored(outer[(i + 1) % outer.size()]), distance) && distance < nearest)
      nearest = distance, hit_edge = static_cast<int>(i);
  }
  for (const auto& hole : other_holes)
    for (std::size_t i = 0; i < hole.size(); ++i) {
      double distance;
      if (ray_hit(mirrored(hole[i]), mirrored(hole[(i + 1) % hole.size()]), distance) && distance < nearest) return -1;
    }
  if (hit_edge < 0) return -1;
  const int a = hit_edge, b = (hit_edge + 1) % static_cast<int>(outer.size());
  int target = mirrored(outer[a]).x() > mirrored(outer[b]).x() ? a : b;
  const Eigen::Vector2d hit = origin + Eigen::Vector2d(nearest, 0);
  const Eigen::Vector2d end = mirrored(outer[target]);
  auto cross = [](const Eigen::Vector2d& p, const Eigen::Vector2d& q) { return p.x() * q.y() - p.y() * q.x(); };
  const double turn = cross(hit - origin, end - origin);
  double best_angle = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < outer.size(); ++i) {
    const Eigen::Vector2d p = mirrored(outer[i]);
    if (static_cast<int>(i) == target || p.x() <= origin.x()) continue;
    // Strictly inside the triangle (origin, hit, end): the bridge to `end` would cross near it.
    const double s1 = cross(hit - origin, p - origin), s2 = cross(end - hit, p - hit),
                 s3 = cross(origin - end, p - end);
    const bool inside = turn > 0 ? (s1 > 0 && s2 > 0 && s3 > 0) : (s1 < 0 && s2 < 0 && s3 < 0);
    if (!inside) continue;
    const double angle = std::abs(std::atan2(p.y() - origin.y(), p.x() - origin.x()));
    if (angle < best_angle) best_angle = angle, target = static_cast<int>(i);
  }
  return target;
}

}  // namespace

std::vector<std::vector<int>> split_holes(std::vector<std::vector<int>> outer,
                                          const std::vector<std::vector<int>>& holes,
                                          const std::vector<Eigen::Vector3d>& points, int axis,
                                          const std::string& face_name) {
  auto planar = [&](const std::vector<int>& loop) {
    std::vector<Eigen::Vector2d> polygon;
    for (int node : loop) polygon.push_back(in_plane(points[node], axis));
    return polygon;
  };
  const std::string failure = "slicing: " + face_name +
                              ": the surface pierces the face in several holes that cannot be bridged; "
                              "change the resolution or the margin";
  std::vector<bool> done(holes.size(), false);
  for (std::size_t h = 0; h < holes.size(); ++h) {
    const std::vector<int>& hole = holes[h];
    const std::vector<Eigen::Vector2d> hole_points = planar(hole);
    int container = -1;
    for (std::size_t o = 0; o < outer.size() && container < 0; ++o)
      if (inside_polygon(hole_points[0], planar(outer[o]))) container = static_cast<int>(o);
    if (container < 0) throw NumericalError(failure);
    std::vector<std::vector<Eigen::Vector2d>> other_holes;
    for (std::size_t k = 0; k < holes.size(); ++k)
      if (k != h && !done[k]) other_holes.push_back(planar(holes[k]));
    auto extreme = [&](double direction) {
      int best = 0;
      for (std::size_t i = 1; i < hole_points.size(); ++i)
        if (direction * hole_points[i].x() > direction * hole_points[best].x()) best = static_cast<int>(i);
      return best;
    };
    const int right = extreme(1.0), left = extreme(-1.0);
    const std::vector<int>& ring = outer[container];
    const std::vector<Eigen::Vector2d> ring_points = planar(ring);
    const int right_target = bridge_target(hole_points[right], 1.0, ring_points, other_holes);
    const int left_target = bridge_target(hole_points[left], -1.0, ring_points, other_holes);
    if (right_target < 0 || left_target < 0 || right_target == left_target || right == left)
      throw NumericalError(failure);
    // Two polygons: along the outer loop from one bridge to the other, across, back along
    // the hole (clockwise, so the region stays on the left), and across again.
    auto walk = [](const std::vector<int>& loop, int from, int to) {
      std::vector<int> nodes{loop[from]};
      for (int i = from; i != to;) nodes.push_back(loop[i = (i + 1) % static_cast<int>(loop.size())]);
      return nodes;
    };
    std::vector<int> first = walk(ring, right_target, left_target), second = walk(ring, left_target, right_target);
    const std::vector<int> hole_left_to_right = walk(hole, left, right), hole_right_to_left = walk(hole, right, left);
    first.insert(first.end(), hole_left_to_right.begin(), hole_left_to_right.end());
    second.insert(second.end(), hole_right_to_left.begin(), hole_right_to_left.end());
    outer[container] = std::move(first);
    outer.push_back(std::move(second));
    done[h] = true;
  }
  return outer;
}

}  // namespace altfem
