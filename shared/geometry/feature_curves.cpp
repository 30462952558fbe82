#include "shared/geometry/feature_curves.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace altfem {

std::vector<Polyline> parts_on_surface(const Polyline& line, const AnalyticShape& shape, double tolerance) {
  const auto on_surface = [&](const Eigen::Vector3d& x) { return std::abs(shape.level_set(x)) <= tolerance; };
  const auto boundary = [&](Eigen::Vector3d on, Eigen::Vector3d off) {
    for (int iteration = 0; iteration < 40; ++iteration) {
      const Eigen::Vector3d middle = 0.5 * (on + off);
      (on_surface(middle) ? on : off) = middle;
    }
    return on;
  };
  std::vector<char> kept(line.size());
  for (std::size_t i = 0; i < line.size(); ++i) kept[i] = on_surface(line[i]);
  if (std::all_of(kept.begin(), kept.end(), [](char k) { return k; })) return {line};
  // A closed line is walked from a sample off the surface so that no run wraps around.
  Polyline walk = line;
  if (line.size() > 2 && line.front() == line.back()) {
    walk.pop_back();
    const auto first_off = std::find(kept.begin(), kept.end() - 1, 0) - kept.begin();
    std::rotate(walk.begin(), walk.begin() + first_off, walk.end());
    walk.push_back(walk.front());
    for (std::size_t i = 0; i < walk.size(); ++i) kept[i] = on_surface(walk[i]);
  }
  std::vector<Polyline> parts;
  Polyline run;
  for (std::size_t i = 0; i < walk.size(); ++i) {
    if (kept[i]) {
      if (run.empty() && i > 0) run.push_back(boundary(walk[i], walk[i - 1]));
      run.push_back(walk[i]);
      continue;
    }
    if (!run.empty()) {
      run.push_back(boundary(walk[i - 1], walk[i]));
      if ((run.front() - run.back()).norm() > tolerance) parts.push_back(run);
      run.clear();
    }
  }
  if (run.size() > 1) parts.push_back(run);
  return parts;
}

std::vector<Polyline> zero_set_on_face(const PlanarFace& face, const AnalyticShape& other, double spacing) {
  const int nu = std::max(2, static_cast<int>(std::ceil(face.u.norm() / spacing)));
  const int nv = std::max(2, static_cast<int>(std::ceil(face.v.norm() / spacing)));
  const auto point = [&](double i, double j) -> Eigen::Vector3d {
    return face.origin + face.u * (i / nu) + face.v * (j / nv);
  };
  std::vector<double> value(static_cast<std::size_t>((nu + 1) * (nv + 1)));
  const auto at = [&](int i, int j) -> double& { return value[static_cast<std::size_t>(i + (nu + 1) * j)]; };
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) at(i, j) = other.level_set(point(i, j));
  const auto inside = [&](int i, int j) { return at(i, j) <= 0; };

  // Crossings keyed by grid edge: (i, j, 0) from (i, j) to (i+1, j); (i, j, 1) to (i, j+1).
  std::map<std::array<int, 3>, int> crossing_index;
  std::vector<Eigen::Vector3d> crossings;
  std::vector<char> on_border;
  const auto crossing = [&](int i, int j, int direction) {
    const std::array<int, 3> key{i, j, direction};
    if (const auto found = crossing_index.find(key); found != crossing_index.end()) return found->second;
    Eigen::Vector3d a = point(i, j), b = direction == 0 ? point(i + 1, j) : point(i, j + 1);
    if (other.level_set(a) > 0) std::swap(a, b);  // a inside, b outside
    for (int iteration = 0; iteration < 50; ++iteration) {
      const Eigen::Vector3d middle = 0.5 * (a + b);
      (other.level_set(middle) <= 0 ? a : b) = middle;
    }
    crossings.push_back(0.5 * (a + b));
    on_border.push_back(direction == 0 ? (j == 0 || j == nv) : (i == 0 || i == nu));
    return crossing_index[key] = static_cast<int>(crossings.size()) - 1;
  };

  std::vector<std::array<int, 2>> segments;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      // The cell's edges in order bottom, right, top, left; a crossing where the ends differ.
      const std::array<std::array<int, 3>, 4> edges{{{i, j, 0}, {i + 1, j, 1}, {i, j + 1, 0}, {i, j, 1}}};
      std::vector<int> found;
      for (const auto& [ei, ej, direction] : edges)
        if (inside(ei, ej) != (direction == 0 ? inside(ei + 1, ej) : inside(ei, ej + 1)))
          found.push_back(crossing(ei, ej, direction));
      if (found.size() == 2) segments.push_back({found[0], found[1]});
      if (found.size() == 4) {
        // A saddle: pair the crossings so that the inside corners the centre shares are joined.
        const bool centre_inside = other.level_set(point(i + 0.5, j + 0.5)) <= 0;
        if (centre_inside == inside(i, j)) {
          segments.push_back({found[0], found[1]});
          segments.push_back({found[2], found[3]});
        } else {
          segments.push_back({found[0], found[3]});
          segments.push_back({found[1], found[2]});
        }
      }
    }

  // Chain the segments: every crossing has one segment (on the border) or two.
  std::vector<std::vector<int>> incident(crossings.size());
  for (int s = 0; s < static_cast<int>(segments.size()); ++s)
    for (int end : segments[s]) incident[end].push_back(s);
  std::vector<char> used(segments.size(), 0);
  std::vector<Polyline> lines;
  const auto walk_from = [&](int start_crossing, int start_segment) {
    Polyline line{crossings[start_crossing]};
    int current = start_crossing, segment = start_segment;
    while (segment >= 0 && !used[segment]) {
      used[segment] = 1;
      current = segments[segment][0] == current ? segments[segment][1] : segments[segment][0];
      line.push_back(crossings[current]);
      segment = -1;
      for (int next : incident[current])
        if (!used[next]) segment = next;
    }
    if (line.size() > 1) lines.push_back(std::move(line));
  };
  for (int c = 0; c < static_cast<int>(crossings.size()); ++c)  // open curves, from the border
    if (on_border[c] && incident[c].size() == 1 && !used[incident[c][0]]) walk_from(c, incident[c][0]);
  for (int s = 0; s < static_cast<int>(segments.size()); ++s)  // closed curves
    if (!used[s]) {
      walk_from(segments[s][0], s);
      lines.back().back() = lines.back().front();
    }
  return lines;
}

void snap_ends(std::vector<Polyline>& lines, double tolerance) {
  std::vector<Eigen::Vector3d> ends;
  for (Polyline& line : lines)
    for (Eigen::Vector3d* end : {&line.front(), &line.back()}) {
      const auto near = std::find_if(ends.begin(), ends.end(),
                                     [&](const Eigen::Vector3d& x) { return (x - *end).norm() <= tolerance; });
      if (near != ends.end()) *end = *near;
      else ends.push_back(*end);
    }
}

}  // namespace altfem
