#include "shared/mesh/split_surface_by_plane.hpp"

#include "shared/mesh/directed_edges.hpp"
#include "shared/mesh/disjoint_sets.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Projection_traits_xy_3.h>
#include <CGAL/Projection_traits_xz_3.h>
#include <CGAL/Projection_traits_yz_3.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace altfem {

namespace {

using cut_curve::Kernel;
using cut_curve::Mesh;
using cut_curve::Point;
using cut_curve::vector_of;

// The cap's triangulation in the blade's plane, projected along the coordinate axis
// nearest its normal (CGAL's xy, xz or yz projection traits: the points' stored
// coordinates, so its predicates are exact). The pencil's sections hold many nearly
// collinear points, on which predicates along the normal itself (Projection_traits_3) fell
// back to exact rationals: 1.2 ms for a section of 70 points, a twentieth of its cut. Each
// vertex knows its point of the split, each face its nesting level (odd inside the section).
template <class Traits>
using CapTriangulation = CGAL::Constrained_Delaunay_triangulation_2<
    Traits,
    CGAL::Triangulation_data_structure_2<
        CGAL::Triangulation_vertex_base_with_info_2<int, Traits>,
        CGAL::Constrained_triangulation_face_base_2<Traits, CGAL::Triangulation_face_base_with_info_2<int, Traits>>>,
    CGAL::No_constraint_intersection_requiring_constructions_tag>;

Eigen::Vector3d crossing_point(const Eigen::Vector3d& from, const Eigen::Vector3d& to, const ExactBlade& blade) {
  const double below = blade.normal.dot(from - blade.a), above = blade.normal.dot(to - blade.a);
  const double t = std::clamp(below / (below - above), 0.0, 1.0);
  return from + (std::isfinite(t) ? t : 0.5) * (to - from);
}

// The points of the split: the piece's vertices (by index), then the crossing points.
struct SplitPoints {
  std::vector<Point> points;
  std::vector<int> input;  // "v:input" of each, −1 for a crossing point
  std::vector<int> side;   // of the blade's plane: 0 for a crossing point
  std::map<std::pair<int, int>, int> crossing_of_edge;

  int crossing(int p, int q, const ExactBlade& blade) {
    const auto key = std::minmax(p, q);
    const auto [slot, inserted] = crossing_of_edge.try_emplace(key, static_cast<int>(points.size()));
    if (inserted) {
      // From the edge's lower index, so the point does not depend on which face asks.
      const Eigen::Vector3d x = crossing_point(vector_of(points[key.first]), vector_of(points[key.second]), blade);
      points.emplace_back(x.x(), x.y(), x.z());
      input.push_back(-1);
      side.push_back(0);
    }
    return slot->second;
  }
};

// A vertex where the plane crosses one of its edges within `snap` of it is taken on the
// plane: a plane within rounding of a vertex would put a cluster of crossing points there
// (coincident after rounding, or slivers that cross once rounded). No point moves, and
// both sides see the same decision, so the cut keeps the volume.
void snap_to_plane(const std::vector<std::array<int, 3>>& triangles, SplitPoints& split, const ExactBlade& blade,
                   double snap) {
  for (const auto& triangle : triangles)
    for (int k = 0; k < 3; ++k) {
      const int p = triangle[k], q = triangle[(k + 1) % 3];
      if (split.side[p] * split.side[q] >= 0) continue;
      const auto key = std::minmax(p, q);
      const Eigen::Vector3d from = vector_of(split.points[key.first]), to = vector_of(split.points[key.second]);
      const Eigen::Vector3d x = crossing_point(from, to, blade);
      const double to_from = (x - from).norm(), to_to = (x - to).norm();
      if (std::min(to_from, to_to) < snap) split.side[to_from <= to_to ? key.first : key.second] = 0;
    }
}

using Edge = std::pair<int, int>;

// Faces of the triangulation by nesting in the border loops, from 0 outside (CGAL's
// "polygon with holes" marking): odd levels lie inside the section. A seam (an edge of the
// side in the plane, both its faces on the side) is crossed at the same level. False when
// a constraint is neither: a point of the border on another loop's edge.
template <class Triangulation>
bool mark_nesting(Triangulation& triangulation, const std::set<Edge>& borders, const std::set<Edge>& seams) {
  using Face_handle = typename Triangulation::Face_handle;
  for (const auto face : triangulation.all_face_handles()) face->info() = -1;
  std::vector<typename Triangulation::Edge> border;
  bool known = true;
  const auto flood = [&](Face_handle start, int level) {
    std::vector<Face_handle> queue{start};
    while (!queue.empty()) {
      const Face_handle face = queue.back();
      queue.pop_back();
      if (face->info() != -1) continue;
      face->info() = level;
      for (int i = 0; i < 3; ++i) {
        const Face_handle neighbour = face->neighbor(i);
        if (neighbour->info() != -1) continue;
        if (!triangulation.is_constrained({face, i})) {
          queue.push_back(neighbour);
          continue;
        }
        const int p = face->vertex(Triangulation::cw(i))->info(), q = face->vertex(Triangulation::ccw(i))->info();
        if (seams.count(std::minmax(p, q))) {
          queue.push_back(neighbour);
        } else {
          known = known && borders.count(std::minmax(p, q));
          border.push_back({face, i});
        }
      }
    }
  };
  flood(triangulation.infinite_face(), 0);
  while (!border.empty()) {
    const typename Triangulation::Edge edge = border.back();
    border.pop_back();
    const Face_handle neighbour = edge.first->neighbor(edge.second);
    if (neighbour->info() == -1) flood(neighbour, edge.first->info() + 1);
  }
  return known;
}

// The cap closing the triangles `faces` (indices into the split's points) of one side: the
// The triangles of the region the border loops enclose, counter-clockwise in the
// projection of `Traits`; nothing when the loops cross or two of their points coincide.
template <class Traits>
std::optional<std::vector<std::array<int, 3>>> triangulate_cap(const SplitPoints& split, const std::set<Edge>& borders,
                                                               const std::set<Edge>& seams) {
  using Triangulation = CapTriangulation<Traits>;
  Triangulation triangulation;
  std::map<int, typename Triangulation::Vertex_handle> vertex_of;
  const auto vertex = [&](int point) {
    const auto found = vertex_of.find(point);
    if (found != vertex_of.end()) return found->second;
    const std::size_t before = triangulation.number_of_vertices();
    const typename Triangulation::Vertex_handle inserted = triangulation.insert(split.points[point]);
    // Two points of the border in one place: no cap of the border's points can close it.
    if (triangulation.number_of_vertices() == before) throw std::runtime_error("coincident border points");
    inserted->info() = point;
    vertex_of.emplace(point, inserted);
    return inserted;
  };
  try {
    for (const std::set<Edge>* constraints : {&borders, &seams})
      for (const auto& [p, q] : *constraints) triangulation.insert_constraint(vertex(p), vertex(q));
  } catch (const std::exception&) {
    return std::nullopt;  // coincident points, or border loops that cross
  }
  if (!mark_nesting(triangulation, borders, seams)) return std::nullopt;
  std::vector<std::array<int, 3>> cap;
  for (const auto face : triangulation.finite_face_handles())
    if (face->info() % 2 == 1)
      cap.push_back({face->vertex(0)->info(), face->vertex(1)->info(), face->vertex(2)->info()});
  return cap;
}

// triangles of the region their border loops enclose, turned to face along `facing`.
// Nothing when the border does not triangulate as disjoint loops.
std::optional<std::vector<std::array<int, 3>>> cap_of(const std::vector<std::array<int, 3>>& faces,
                                                      const SplitPoints& split, const Eigen::Vector3d& facing) {
  const std::vector<DirectedEdge> edges = directed_edges(faces);
  std::set<Edge> borders, seams;
  const bool single = for_each_edge(edges, [&](int a, int b, auto forward, auto backward) {
    const auto count = [](auto uses) { return uses.second - uses.first; };
    if (count(forward) > 1 || count(backward) > 1) return false;  // a face twice, or a split face over another
    if (count(forward) + count(backward) == 1) borders.insert({a, b});
    else if (split.side[a] == 0 && split.side[b] == 0)
      seams.insert({a, b});  // the cap must hold it, e.g. a valley's edge with both sides in the section
    return true;
  });
  if (!single) return std::nullopt;
  // Dropping the axis nearest the normal; a projection that sees the plane from behind
  // (the normal's component there negative) turns the cap, which must face along `facing`.
  Eigen::Index axis = 0;
  facing.cwiseAbs().maxCoeff(&axis);
  const bool turned = (axis == 1) == (facing[axis] > 0);  // xz's orientation is y's opposite
  std::optional<std::vector<std::array<int, 3>>> cap =
      axis == 0   ? triangulate_cap<CGAL::Projection_traits_yz_3<Kernel>>(split, borders, seams)
      : axis == 1 ? triangulate_cap<CGAL::Projection_traits_xz_3<Kernel>>(split, borders, seams)
                  : triangulate_cap<CGAL::Projection_traits_xy_3<Kernel>>(split, borders, seams);
  if (cap && turned)
    for (std::array<int, 3>& triangle : *cap) std::swap(triangle[1], triangle[2]);
  return cap;
}

// For each corner k of each face f, the face across its edge (f[k], f[k+1]) and that
// face's corner at f[k+1]; nothing when an edge cannot be paired. An edge has more than two
// faces where a section touches itself along it (a valley's edge with the cap on both
// sides): there each face off the plane pairs with the one whose third corner lies
// strictly behind it (in its material, an exact orientation), the cap's faces with what
// is left.
std::optional<std::vector<std::array<std::pair<int, int>, 3>>> pair_faces(const std::vector<std::array<int, 3>>& faces,
                                                                          const SplitPoints& split) {
  const std::vector<DirectedEdge> edges = directed_edges(faces);
  std::vector<std::array<std::pair<int, int>, 3>> across(faces.size());
  const auto join = [&](const DirectedEdge& a, const DirectedEdge& b) {
    across[a.face][a.corner] = {b.face, b.corner};  // the edges run opposite ways: b's first corner is a's second
    across[b.face][b.corner] = {a.face, a.corner};
  };
  const auto in_plane = [&](int f) {
    return split.side[faces[f][0]] == 0 && split.side[faces[f][1]] == 0 && split.side[faces[f][2]] == 0;
  };
  const bool paired = for_each_edge(edges, [&](int, int, auto forward_uses, auto backward_uses) {
    const auto [first, last] = forward_uses;
    const auto [reverse_first, reverse_last] = backward_uses;
    if (first == last) return true;
    if (reverse_last - reverse_first != last - first) return false;
    if (last - first == 1) {
      join(*first, *reverse_first);
      return true;
    }
    std::vector<DirectedEdge> ahead(first, last), backward(reverse_first, reverse_last);
    // Off the plane first, each to its one partner behind it.
    for (auto* side : {&ahead, &backward}) {
      auto* other = side == &ahead ? &backward : &ahead;
      for (auto use = side->begin(); use != side->end();) {
        if (in_plane(use->face)) {
          ++use;
          continue;
        }
        const auto& face = faces[use->face];
        auto partner = other->end();
        int behind = 0;
        for (auto candidate = other->begin(); candidate != other->end(); ++candidate) {
          const int third = faces[candidate->face][(candidate->corner + 2) % 3];
          if (CGAL::orientation(split.points[face[0]], split.points[face[1]], split.points[face[2]],
                                split.points[third]) == CGAL::NEGATIVE) {
            partner = candidate;
            ++behind;
          }
        }
        if (behind != 1) return false;
        join(*use, *partner);
        other->erase(partner);
        use = side->erase(use);
      }
    }
    if (ahead.size() > 1 || ahead.size() != backward.size()) return false;
    if (ahead.size() == 1) join(ahead[0], backward[0]);
    return true;
  });
  if (!paired) return std::nullopt;
  return across;
}

// The side's faces and cap as a Surface_mesh with "v:input", a point in several places of
// it (where the section touches itself) once per fan of faces around it; nothing when it
// is not a closed manifold.
std::optional<Mesh> side_mesh(const std::vector<std::array<int, 3>>& faces, const SplitPoints& split) {
  const auto across = pair_faces(faces, split);
  if (!across) return std::nullopt;
  // Corners (face, k) joined across each edge at its two ends: each set is one vertex.
  DisjointSets fans(3 * static_cast<int>(faces.size()));
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const auto [g, at_next] = (*across)[f][k];  // g's corner at faces[f][k + 1]
      fans.join(3 * static_cast<int>(f) + (k + 1) % 3, 3 * g + at_next);
      fans.join(3 * static_cast<int>(f) + k, 3 * g + (at_next + 1) % 3);
    }
  Mesh mesh;
  // A recycled slot would keep a removed vertex's "v:input" (the curve's clean-up and the
  // cap's remeshing remove and add vertices): new vertices go at the end.
  mesh.set_recycle_garbage(false);
  auto input_of = mesh.add_property_map<Mesh::Vertex_index, int>("v:input", -1).first;
  // The vertices by point, then by fan, so that the mesh does not depend on face order.
  std::vector<std::pair<int, int>> point_and_fan;
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (int k = 0; k < 3; ++k) point_and_fan.push_back({faces[f][k], fans.find(3 * static_cast<int>(f) + k)});
  std::sort(point_and_fan.begin(), point_and_fan.end());
  point_and_fan.erase(std::unique(point_and_fan.begin(), point_and_fan.end()), point_and_fan.end());
  std::vector<Mesh::Vertex_index> vertex_of_fan(3 * faces.size());
  for (const auto& [point, fan] : point_and_fan) {
    const Mesh::Vertex_index v = mesh.add_vertex(split.points[point]);
    input_of[v] = split.input[point];
    vertex_of_fan[fan] = v;
  }
  // The connectivity set directly from the pairing (Euler::add_face would search each
  // vertex's faces for it): halfedge (f, k) runs from corner k to k + 1 and is the opposite
  // of its partner's (g, corner at f[k + 1]). Every edge is paired and each fan is one cycle
  // of corners around its vertex, so the mesh is a closed manifold.
  std::vector<Mesh::Halfedge_index> halfedge_of(3 * faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const auto [g, at_next] = (*across)[f][k];
      const std::size_t here = 3 * f + k, there = 3 * static_cast<std::size_t>(g) + at_next;
      if (here > there) continue;
      halfedge_of[here] = mesh.add_edge();
      halfedge_of[there] = mesh.opposite(halfedge_of[here]);
    }
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const Mesh::Face_index face = mesh.add_face();
    for (int k = 0; k < 3; ++k) {
      const Mesh::Halfedge_index h = halfedge_of[3 * f + k];
      const Mesh::Vertex_index target = vertex_of_fan[fans.find(3 * static_cast<int>(f) + (k + 1) % 3)];
      mesh.set_target(h, target);
      mesh.set_halfedge(target, h);
      mesh.set_next(h, halfedge_of[3 * f + (k + 1) % 3]);
      mesh.set_face(h, face);
    }
    mesh.set_halfedge(face, halfedge_of[3 * f]);
  }
  return mesh;
}

}  // namespace

std::optional<PlaneSplit> split_surface_by_plane(TrianglePiece piece, const ExactBlade& blade, double snap) {
  SplitPoints split;
  split.points = std::move(piece.points);
  split.input = std::move(piece.input);
  for (const Point& point : split.points) split.side.push_back(blade.side(vector_of(point)));
  std::vector<std::array<int, 3>> triangles = std::move(piece.triangles);
  snap_to_plane(triangles, split, blade, snap);
  PlaneSplit result;
  for (std::size_t point = 0; point < split.points.size(); ++point)
    if (split.side[point] == 0) result.inputs_on_plane.push_back(split.input[point]);
  std::sort(result.inputs_on_plane.begin(), result.inputs_on_plane.end());
  result.grazes = std::find(split.side.begin(), split.side.end(), -1) == split.side.end() ||
                  std::find(split.side.begin(), split.side.end(), +1) == split.side.end();
  if (result.grazes) return result;
  std::array<std::vector<std::array<int, 3>>, 2> faces;  // [0] below, [1] above
  for (const std::array<int, 3>& point : triangles) {
    const std::array<int, 3> sides = {split.side[point[0]], split.side[point[1]], split.side[point[2]]};
    if (sides == std::array<int, 3>{0, 0, 0}) {
      // A face in the plane bounds the material on the side it faces away from.
      const Eigen::Vector3d a = vector_of(split.points[point[0]]), b = vector_of(split.points[point[1]]),
                            c = vector_of(split.points[point[2]]);
      faces[(b - a).cross(c - a).dot(blade.normal) > 0 ? 0 : 1].push_back(point);
      continue;
    }
    for (const int sign : {-1, +1}) {
      // The face's piece on this side: its corners there or on the plane, and where its
      // edges cross; a convex polygon, so a fan.
      std::array<int, 4> polygon{};
      int size = 0;
      bool reaches = false;
      for (int corner = 0; corner < 3; ++corner) {
        const int next = (corner + 1) % 3;
        if (sides[corner] * sign >= 0) polygon[size++] = point[corner];
        reaches = reaches || sides[corner] == sign;
        if (sides[corner] * sides[next] < 0) polygon[size++] = split.crossing(point[corner], point[next], blade);
      }
      if (!reaches) continue;
      for (int j = 1; j + 1 < size; ++j) faces[sign > 0].push_back({polygon[0], polygon[j], polygon[j + 1]});
    }
  }
  for (const int below_or_above : {0, 1}) {
    // The cap faces away from its side's material: along the normal below, against it above.
    const Eigen::Vector3d facing = below_or_above == 0 ? blade.normal : Eigen::Vector3d(-blade.normal);
    const auto cap = cap_of(faces[below_or_above], split, facing);
    if (!cap || cap->empty()) return std::nullopt;
    std::vector<std::array<int, 3>> closed = faces[below_or_above];
    closed.insert(closed.end(), cap->begin(), cap->end());
    auto mesh = side_mesh(closed, split);
    if (!mesh) return std::nullopt;
    result.sides[below_or_above] = std::move(*mesh);
  }
  return result;
}

}  // namespace altfem
