#include "shared/mesh/split_holes.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <limits>

#include "shared/common/error.hpp"

namespace altfem {

namespace {

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
                                          const std::function<Eigen::Vector2d(int)>& in_plane,
                                          const std::string& failure) {
  auto planar = [&](const std::vector<int>& loop) {
    std::vector<Eigen::Vector2d> polygon;
    for (int node : loop) polygon.push_back(in_plane(node));
    return polygon;
  };
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

std::function<Eigen::Vector2d(int)> plane_coordinates(const std::vector<Eigen::Vector3d>& points,
                                                      const Eigen::Vector3d& normal) {
  const Eigen::Vector3d n = normal.normalized();
  Eigen::Index smallest = 0;
  n.cwiseAbs().minCoeff(&smallest);
  const Eigen::Vector3d u = n.cross(Eigen::Vector3d::Unit(smallest)).normalized(), v = n.cross(u);
  return [&points, u, v](int node) { return Eigen::Vector2d(points[node].dot(u), points[node].dot(v)); };
}

}  // namespace altfem
