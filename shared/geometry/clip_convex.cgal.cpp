#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "shared/geometry/clip_convex.hpp"

namespace altfem {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

Point to_point(const Eigen::Vector3d& x) { return Point(x.x(), x.y(), x.z()); }

/// A convex polytope as a boundary: faces list vertex indices counter-clockwise seen
/// from outside, stored flat (face f is indices[start[f]], …, indices[start[f + 1] − 1]).
/// Vertices no face uses may remain (they are ignored).
struct ConvexPolytope {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<int> indices;
  std::vector<int> start;  ///< #faces + 1

  int face_count() const { return static_cast<int>(start.size()) - 1; }
  void clear_faces() {
    indices.clear();
    start.assign(1, 0);
  }
  void close_face() { start.push_back(static_cast<int>(indices.size())); }
};

/// Scratch of one clipping, reused: clipping runs for every candidate tetrahedron of
/// every cut cell, and these few small arrays were most of its time as allocations.
struct ClipWorkspace {
  ConvexPolytope polytope, clipped;
  std::vector<int> side, cap;
  std::vector<char> in_cap;
  std::vector<std::array<int, 3>> edge_vertex;  ///< (u, v, new vertex) per cut edge, u < v
  std::vector<std::pair<double, int>> angles;
};

/// -1 kept side (inside), 0 on the plane, +1 outside: one exact predicate.
int side_of(const ClipPlane& plane, const Eigen::Vector3d& x) {
  const CGAL::Orientation orientation =
      CGAL::orientation(to_point(plane.a), to_point(plane.b), to_point(plane.c), to_point(x));
  return orientation == CGAL::NEGATIVE ? -1 : (orientation == CGAL::ZERO ? 0 : 1);
}

enum class ClipOutcome { unchanged, cut, empty };

/// Of a polytope's diagonal, the distance from a plane within which a vertex is a rounding
/// of one on it.
constexpr double rounding_fraction = 1e-14;

/// Cuts `workspace.polytope` by one plane in place.
ClipOutcome clip_by_plane(ClipWorkspace& workspace, const ClipPlane& plane) {
  ConvexPolytope& polytope = workspace.polytope;
  const int vertex_count = static_cast<int>(polytope.vertices.size());
  std::vector<int>& side = workspace.side;
  // Each used vertex's side once (a vertex is in three faces or more, each listing it):
  // `unknown` until its first face asks.
  constexpr int unknown = 2;
  side.assign(vertex_count, unknown);
  bool any_inside = false, any_outside = false;
  for (const int v : polytope.indices) {
    if (side[v] != unknown) continue;
    side[v] = side_of(plane, polytope.vertices[v]);
    any_inside |= side[v] < 0;
    any_outside |= side[v] > 0;
  }
  if (!any_outside) return ClipOutcome::unchanged;  // kept side (faces on the plane included)
  if (!any_inside) return ClipOutcome::empty;       // outside, or flat on the plane
  // Every vertex of one side within a rounding of the plane (a corner a cut rounded off a
  // cell's face or edge): the other side holds the polytope. Cut there, the new vertices
  // would lie a few ulps from the old and from one another, and the next plane through
  // them could fold the piece (a clip of 1.04 times its tetrahedron's volume).
  {
    const Eigen::Vector3d unit = (plane.b - plane.a).cross(plane.c - plane.a).normalized();
    double farthest_out = 0, farthest_in = 0;
    Eigen::AlignedBox3d box;
    for (const int v : polytope.indices) {
      const double distance = (polytope.vertices[v] - plane.a).dot(unit);
      if (side[v] > 0) farthest_out = std::max(farthest_out, distance);
      if (side[v] < 0) farthest_in = std::max(farthest_in, -distance);
      box.extend(polytope.vertices[v]);
    }
    const double rounding = rounding_fraction * box.diagonal().norm();
    if (farthest_out <= rounding) return ClipOutcome::unchanged;
    if (farthest_in <= rounding) return ClipOutcome::empty;
  }

  // Signed distances along the (unnormalised) normal only place the new vertices;
  // which edges are cut was decided exactly above.
  const Eigen::Vector3d normal = (plane.b - plane.a).cross(plane.c - plane.a);
  workspace.edge_vertex.clear();  // each cut edge's new vertex, shared by its two faces
  const auto cut_edge = [&](int u, int v) {
    const auto [low, high] = std::minmax(u, v);
    for (const auto& [first, second, vertex] : workspace.edge_vertex) {
      if (first == low && second == high) return vertex;
    }
    const Eigen::Vector3d& p = polytope.vertices[low];
    const Eigen::Vector3d& q = polytope.vertices[high];
    const double dp = (p - plane.a).dot(normal), dq = (q - plane.a).dot(normal);
    // The exact predicates put p and q strictly on opposite sides, but the rounded
    // distances of nearly-on points may not agree in sign: |dp| / (|dp| + |dq|) is the
    // same parameter when they do and stays in [0, 1] when they do not.
    const double sum = std::abs(dp) + std::abs(dq);
    const double t = sum > 0.0 ? std::abs(dp) / sum : 0.5;
    polytope.vertices.push_back(p + t * (q - p));
    const int index = static_cast<int>(polytope.vertices.size()) - 1;
    workspace.edge_vertex.push_back({low, high, index});
    return index;
  };

  ConvexPolytope& kept = workspace.clipped;  // the kept faces
  kept.clear_faces();
  std::vector<int>& cap = workspace.cap;  // vertices on the plane: the new face
  cap.clear();
  std::vector<char>& in_cap = workspace.in_cap;
  in_cap.assign(vertex_count, 0);
  for (int f = 0; f < polytope.face_count(); ++f) {
    const int begin = polytope.start[f], n = polytope.start[f + 1] - begin;
    for (int i = 0; i < n; ++i) {
      const int u = polytope.indices[begin + i], v = polytope.indices[begin + (i + 1) % n];
      if (side[u] <= 0) kept.indices.push_back(u);
      if (side[u] == 0 && !in_cap[u]) {
        in_cap[u] = 1;
        cap.push_back(u);
      }
      if (side[u] * side[v] < 0) {
        const int w = cut_edge(u, v);
        kept.indices.push_back(w);
        if (static_cast<int>(in_cap.size()) <= w) in_cap.resize(w + 1, 0);
        if (!in_cap[w]) {
          in_cap[w] = 1;
          cap.push_back(w);
        }
      }
    }
    if (static_cast<int>(kept.indices.size()) - kept.start.back() >= 3) {
      kept.close_face();
    } else {
      kept.indices.resize(kept.start.back());
    }
  }
  if (cap.size() >= 3) {
    // Order the cap counter-clockwise seen from outside (along +normal) around its centroid.
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (const int v : cap) centre += polytope.vertices[v];
    centre /= static_cast<double>(cap.size());
    const Eigen::Vector3d unit_normal = normal.normalized();
    const Eigen::Vector3d first = (polytope.vertices[cap[0]] - centre).normalized();
    const Eigen::Vector3d second = unit_normal.cross(first);
    std::vector<std::pair<double, int>>& angles = workspace.angles;
    angles.clear();
    for (const int v : cap) {
      const Eigen::Vector3d d = polytope.vertices[v] - centre;
      angles.emplace_back(std::atan2(d.dot(second), d.dot(first)), v);
    }
    std::sort(angles.begin(), angles.end());
    for (const auto& [angle, v] : angles) kept.indices.push_back(v);
    kept.close_face();
  }
  std::swap(polytope.indices, kept.indices);
  std::swap(polytope.start, kept.start);
  return polytope.face_count() >= 4 ? ClipOutcome::cut : ClipOutcome::empty;
}

}  // namespace

std::vector<TetrahedronCorners> clip_tetrahedron(const TetrahedronCorners& tetrahedron,
                                                 const std::vector<ClipPlane>& planes, PieceFan fan) {
  thread_local ClipWorkspace workspace;
  ConvexPolytope& polytope = workspace.polytope;
  polytope.vertices.clear();
  for (int i = 0; i < 4; ++i) polytope.vertices.push_back(tetrahedron.row(i).transpose());
  // Outward counter-clockwise faces of a positively oriented tetrahedron (VTK order);
  // a negatively oriented one is reordered first.
  if (CGAL::orientation(to_point(polytope.vertices[0]), to_point(polytope.vertices[1]), to_point(polytope.vertices[2]),
                        to_point(polytope.vertices[3])) != CGAL::POSITIVE) {
    std::swap(polytope.vertices[1], polytope.vertices[2]);
  }
  polytope.indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  polytope.start = {0, 3, 6, 9, 12};
  bool cut = false;
  for (const ClipPlane& plane : planes) {
    const ClipOutcome outcome = clip_by_plane(workspace, plane);
    if (outcome == ClipOutcome::empty) return {};
    cut |= outcome == ClipOutcome::cut;
  }
  if (!cut) {
    // Entirely inside: the tetrahedron itself, positively oriented.
    TetrahedronCorners whole;
    for (int i = 0; i < 4; ++i) whole.row(i) = polytope.vertices[i].transpose();
    return {whole};
  }

  // Fan from the centroid of the used vertices: every (centroid, face triangle) is a
  // positively oriented tetrahedron of the convex piece; flat ones add no volume. From a
  // vertex of the piece instead, the faces through it would give flat ones only and are
  // passed over; the apex lies behind every other face's plane (the piece is convex).
  std::vector<char>& used = workspace.in_cap;
  used.assign(polytope.vertices.size(), 0);
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  int used_count = 0;
  for (const int v : polytope.indices) {
    if (!used[v]) {
      used[v] = 1;
      centroid += polytope.vertices[v];
      ++used_count;
    }
  }
  centroid /= used_count;
  const int apex = polytope.indices.front();
  const Eigen::Vector3d start = fan == PieceFan::vertex ? polytope.vertices[apex] : centroid;
  std::vector<TetrahedronCorners> pieces;
  for (int f = 0; f < polytope.face_count(); ++f) {
    const int* face = polytope.indices.data() + polytope.start[f];
    const int n = polytope.start[f + 1] - polytope.start[f];
    if (fan == PieceFan::vertex && std::find(face, face + n, apex) != face + n) continue;
    for (int i = 1; i + 1 < n; ++i) {
      TetrahedronCorners piece;
      piece.row(0) = start.transpose();
      piece.row(1) = polytope.vertices[face[0]].transpose();
      piece.row(2) = polytope.vertices[face[i]].transpose();
      piece.row(3) = polytope.vertices[face[i + 1]].transpose();
      const Eigen::Matrix3d edges = (piece.bottomRows<3>().rowwise() - piece.row(0)).transpose();
      if (edges.determinant() > 0.0) pieces.push_back(piece);
    }
  }
  return pieces;
}

std::vector<ClipPlane> hexahedron_clip_planes(const Eigen::Ref<const Eigen::MatrixXd>& corners) {
  // VTK hexahedron faces, counter-clockwise seen from outside.
  static constexpr int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                      {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  std::vector<ClipPlane> planes;
  for (const auto& face : faces) {
    planes.push_back(
        {corners.row(face[0]).transpose(), corners.row(face[1]).transpose(), corners.row(face[2]).transpose()});
  }
  return planes;
}

std::vector<ClipPlane> tetrahedron_clip_planes(const Eigen::Ref<const Eigen::MatrixXd>& corners) {
  static constexpr int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  std::vector<ClipPlane> planes;
  for (const auto& face : faces) {
    planes.push_back(
        {corners.row(face[0]).transpose(), corners.row(face[1]).transpose(), corners.row(face[2]).transpose()});
  }
  return planes;
}

bool hexahedron_faces_planar(const Eigen::Ref<const Eigen::MatrixXd>& corners, double relative_tolerance) {
  const std::vector<ClipPlane> planes = hexahedron_clip_planes(corners);
  static constexpr int fourth[6] = {1, 7, 4, 5, 6, 7};
  for (int f = 0; f < 6; ++f) {
    const Eigen::Vector3d x = corners.row(fourth[f]).transpose();
    if (side_of(planes[f], x) == 0) continue;
    // Not exactly coplanar: accept the rounding of corners computed by a map.
    const Eigen::Vector3d normal = (planes[f].b - planes[f].a).cross(planes[f].c - planes[f].a);
    const double size = std::max((planes[f].b - planes[f].a).norm(), (planes[f].c - planes[f].a).norm());
    if (!(std::abs((x - planes[f].a).dot(normal.normalized())) <= relative_tolerance * size)) return false;
  }
  return true;
}

}  // namespace altfem
