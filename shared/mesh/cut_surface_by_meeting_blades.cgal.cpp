// A closed piece cut by finite blades that meet one another inside it (an X or a T of two
// notches, a V of two polygons): their union is no surface corefinement can split by (it
// intersects itself, and where three or four sheets meet along a line no manifold mesh
// holds it). So nothing is split here: the piece is refined along each blade's curve and
// each cap (a blade clipped to the body) along the others', one corefinement at a time,
// and the output's triangles — the piece's, and each cap's once per side — find their
// neighbours across every edge by the order in which they turn about it, as the material
// between them goes: an edge that the body's surface and caps share, or caps along the line
// where they meet, is held by four, six or eight triangles, and each pair that bounds one
// wedge of material is joined there. A vertex gets one copy per fan of triangles so
// joined (four where two notches cross on the surface, one where a notch ends).
#include <CGAL/Polygon_mesh_processing/clip.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

#include "shared/mesh/cut_surface_pieces.hpp"
#include "shared/mesh/disjoint_sets.hpp"

namespace altfem::surface_cut {

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;

// The points of the piece and its caps, one index per position: a cap's point of the cut
// curve is the piece's but for rounding (the same intersection, constructed from other
// operands where another blade refined the piece's edge first), so points within
// `tolerance` of an earlier one are it.
class WeldedPoints {
public:
  explicit WeldedPoints(double tolerance) : tolerance_(tolerance) {}

  int index_of(const Eigen::Vector3d& point) {
    const Cell cell = cell_of(point);
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz) {
          const auto found = cells_.find({cell[0] + dx, cell[1] + dy, cell[2] + dz});
          if (found == cells_.end()) continue;
          for (const int index : found->second)
            if ((positions[index] - point).norm() <= tolerance_) return index;
        }
    positions.push_back(point);
    cells_[cell].push_back(static_cast<int>(positions.size()) - 1);
    return static_cast<int>(positions.size()) - 1;
  }

  std::vector<Eigen::Vector3d> positions;

private:
  using Cell = std::array<long long, 3>;
  Cell cell_of(const Eigen::Vector3d& point) const {
    const double size = 4 * tolerance_;
    return {static_cast<long long>(std::floor(point.x() / size)), static_cast<long long>(std::floor(point.y() / size)),
            static_cast<long long>(std::floor(point.z() / size))};
  }
  double tolerance_;
  std::map<Cell, std::vector<int>> cells_;
};

struct Triangle {
  std::array<int, 3> corners;  // welded points, turning about the outward normal
  bool cap = false;
};

// Per triangle and corner, the triangle that shares its edge from that corner to the next
// and bounds the same wedge of material, found for every edge by turning about it.
// Throws std::runtime_error where the triangles about an edge do not alternate between a
// side of material and a side of void (blades that overlap in one plane, a rounding that
// put two in the wrong order).
std::vector<std::array<int, 3>> neighbours_across_edges(const std::vector<Triangle>& triangles,
                                                        const std::vector<Eigen::Vector3d>& points) {
  std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> holders;  // edge → (triangle, corner)
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int from = triangles[t].corners[k], to = triangles[t].corners[(k + 1) % 3];
      holders[std::minmax(from, to)].push_back({static_cast<int>(t), k});
    }
  std::vector<std::array<int, 3>> neighbour(triangles.size(), {-1, -1, -1});
  for (const auto& [edge, held] : holders) {
    if (held.size() % 2 != 0) throw std::runtime_error("an edge of the cut is held by an odd number of triangles");
    const Eigen::Vector3d p = points[edge.first], axis = (points[edge.second] - p).normalized();
    const Eigen::Vector3d u = axis.unitOrthogonal(), w = axis.cross(u);
    // Each triangle's angle about the edge, and whether its material lies after it
    // (its outward normal turns back): at one angle (a cap's two sides) the one whose
    // material lies before comes first.
    struct Turn {
      double angle;
      bool material_after;
      int triangle, corner;
    };
    std::vector<Turn> turns;
    for (const auto& [t, k] : held) {
      const std::array<int, 3>& c = triangles[t].corners;
      const Eigen::Vector3d v = points[c[(k + 2) % 3]] - p;
      const Eigen::Vector3d normal = (points[c[1]] - points[c[0]]).cross(points[c[2]] - points[c[0]]);
      turns.push_back({std::atan2(v.dot(w), v.dot(u)), normal.dot(axis.cross(v)) < 0, t, k});
    }
    std::sort(turns.begin(), turns.end(), [](const Turn& a, const Turn& b) {
      return a.angle < b.angle || (a.angle == b.angle && !a.material_after && b.material_after);
    });
    // Material between consecutive triangles where the first's lies after it and the
    // second's before: a wedge of void between the others. Start after a void.
    const std::size_t n = turns.size();
    std::size_t start = 0;
    while (start < n && !turns[start].material_after) ++start;
    for (std::size_t i = 0; i < n; i += 2) {
      const Turn& first = turns[(start + i) % n];
      const Turn& second = turns[(start + i + 1) % n];
      const bool opposite = triangles[first.triangle].corners[first.corner] ==
                            triangles[second.triangle].corners[(second.corner + 1) % 3];
      if (!first.material_after || second.material_after || !opposite) {
        const Eigen::Vector3d middle = (p + points[edge.second]) / 2;
        throw std::runtime_error("the triangles about the cut's edge at (" + std::to_string(middle.x()) + ", " +
                                 std::to_string(middle.y()) + ", " + std::to_string(middle.z()) +
                                 ") do not alternate between material and void");
      }
      neighbour[first.triangle][first.corner] = second.triangle;
      neighbour[second.triangle][second.corner] = first.triangle;
    }
  }
  return neighbour;
}

// The triangle `corners` split where `candidates` lie inside its edges (within
// `tolerance` of an edge, strictly between its ends): fanned from the corner opposite the
// one edge that holds any, or from a new point at its centroid where several do.
std::vector<std::array<int, 3>> split_at_points(const std::array<int, 3>& corners, const std::vector<int>& candidates,
                                                WeldedPoints& points, double tolerance) {
  std::array<std::vector<std::pair<double, int>>, 3> inside;  // per edge: (parameter along it, point)
  int split_edges = 0;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d a = points.positions[corners[k]], b = points.positions[corners[(k + 1) % 3]];
    const double length = (b - a).norm();
    for (const int candidate : candidates) {
      const Eigen::Vector3d p = points.positions[candidate];
      const double along = (p - a).dot(b - a) / (length * length);
      if (along * length > tolerance && (1 - along) * length > tolerance &&
          (a + along * (b - a) - p).norm() <= tolerance)
        inside[k].push_back({along, candidate});
    }
    std::sort(inside[k].begin(), inside[k].end());
    split_edges += inside[k].empty() ? 0 : 1;
  }
  if (split_edges == 0) return {corners};
  std::vector<int> loop;  // the corners and the points inside the edges, in order
  for (int k = 0; k < 3; ++k) {
    loop.push_back(corners[k]);
    for (const auto& [along, point] : inside[k]) loop.push_back(point);
  }
  std::vector<std::array<int, 3>> parts;
  if (split_edges == 1) {
    const int edge = static_cast<int>(
        std::find_if(inside.begin(), inside.end(), [](const auto& points_inside) { return !points_inside.empty(); }) -
        inside.begin());
    std::rotate(loop.begin(), std::find(loop.begin(), loop.end(), corners[(edge + 2) % 3]), loop.end());
    for (std::size_t k = 1; k + 1 < loop.size(); ++k) parts.push_back({loop[0], loop[k], loop[k + 1]});
    return parts;
  }
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const int corner : corners) centroid += points.positions[corner] / 3;
  const int centre = points.index_of(centroid);
  for (std::size_t k = 0; k < loop.size(); ++k) parts.push_back({centre, loop[k], loop[(k + 1) % loop.size()]});
  return parts;
}

}  // namespace

bool cut_piece_by_meeting_blades(Mesh& piece, const std::vector<Mesh>& blades, const std::vector<bool>& planar,
                                 double edge_length, CutPieces& out) {
  Mesh body = piece;  // the caps' clipper (clip leaves it as it is)
  // The piece refined along every blade's curve, one blade at a time (each free of
  // self-intersections, as the piece stays); nothing split.
  for (const Mesh& blade : blades) {
    Mesh refined_blade = blade;
    PMP::corefine(piece, refined_blade);
  }
  renumber_by_position(piece);
  std::vector<Mesh> caps;
  for (std::size_t b = 0; b < blades.size(); ++b) {
    Mesh cap = blades[b];
    PMP::clip(cap, body, CGAL::parameters::clip_volume(false), CGAL::parameters::do_not_modify(true));
    cap.collect_garbage();
    PMP::triangulate_faces(cap);
    if (planar[b])
      cut_curve::remesh_cap(
          cap, [](Mesh::Face_index) { return true; }, edge_length);
    caps.push_back(std::move(cap));
  }
  // Each cap refined along the line where it meets each other cap.
  for (std::size_t a = 0; a < caps.size(); ++a)
    for (std::size_t b = a + 1; b < caps.size(); ++b)
      if (caps[a].number_of_faces() > 0 && caps[b].number_of_faces() > 0) PMP::corefine(caps[a], caps[b]);
  for (Mesh& cap : caps) renumber_by_position(cap);

  // The output's triangles on welded points: the piece's, then each cap's once per side,
  // facing away from that side's material (the blade's triangles turn about its normal,
  // so the positive side's are turned over).
  const double same_point = 1e-12 * 40 * edge_length;  // of the piece's diagonal
  WeldedPoints points(same_point);
  const auto input_of = piece.property_map<Mesh::Vertex_index, int>("v:input").first;
  std::vector<int> input_at;  // per welded point: the input vertex there, or −1
  const auto corner_points = [&](const Mesh& mesh, Mesh::Face_index f, bool is_piece) {
    std::array<int, 3> corners;
    int k = 0;
    for (const Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      corners[k] = points.index_of(vector_of(mesh.point(v)));
      input_at.resize(points.positions.size(), -1);
      if (is_piece && input_of[v] >= 0) input_at[corners[k]] = input_of[v];
      ++k;
    }
    return corners;
  };
  // A sliver whose corners weld (where the caps or the piece's refinements cross a
  // rounding apart) is dropped: its neighbours then share its welded edge.
  const auto has_size = [](const std::array<int, 3>& c) { return c[0] != c[1] && c[1] != c[2] && c[2] != c[0]; };
  std::vector<Triangle> triangles;
  for (const Mesh::Face_index f : piece.faces())
    if (const std::array<int, 3> corners = corner_points(piece, f, true); has_size(corners))
      triangles.push_back({corners, false});
  const std::size_t piece_triangles = triangles.size();
  // A cap's border holds the points where its blade crosses the body's edges; the piece's
  // curve also those where it crosses the edges another blade's refinement made (the caps
  // are clipped to the body before: clipped to the refined one, whose curves lie in their
  // planes to a rounding, they came out as slivers). Those points split the caps' edges.
  std::vector<int> curve_points;
  for (const Mesh::Vertex_index v : piece.vertices())
    if (input_of[v] < 0) curve_points.push_back(points.index_of(vector_of(piece.point(v))));
  for (const Mesh& cap : caps)
    for (const Mesh::Face_index f : cap.faces())
      if (const std::array<int, 3> corners = corner_points(cap, f, false); has_size(corners))
        for (const std::array<int, 3>& part : split_at_points(corners, curve_points, points, same_point)) {
          triangles.push_back({part, true});
          triangles.push_back({{part[0], part[2], part[1]}, true});
        }
  if (triangles.size() == piece_triangles) return false;  // no blade inside the body
  input_at.resize(points.positions.size(), -1);
  const std::vector<std::array<int, 3>> neighbour = neighbours_across_edges(triangles, points.positions);

  // A vertex per fan: the corners of two neighbours at the ends of their shared edge are one.
  DisjointSets fans(static_cast<int>(3 * triangles.size()));
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const auto other = static_cast<std::size_t>(neighbour[t][k]);
      for (const int end : {k, (k + 1) % 3})
        for (int j = 0; j < 3; ++j)
          if (triangles[other].corners[j] == triangles[t].corners[end])
            fans.join(static_cast<int>(3 * t) + end, static_cast<int>(3 * other) + j);
    }
  // Each fan's vertex: the input's where it holds an input vertex not yet taken (its index
  // kept), else a new one, on the cut.
  std::map<int, int> vertex_of_fan;
  std::vector<char> taken(static_cast<std::size_t>(out.input_count), 0);
  const auto vertex_of = [&](std::size_t t, int k) {
    const int fan = fans.find(static_cast<int>(3 * t + static_cast<std::size_t>(k)));
    const auto [slot, inserted] = vertex_of_fan.try_emplace(fan, -1);
    if (!inserted) return slot->second;
    const int point = triangles[t].corners[k];
    if (const int input = input_at[point]; input >= 0 && !taken[input]) {
      taken[input] = 1;
      slot->second = input;
    } else {
      slot->second = static_cast<int>(out.input_count + static_cast<Eigen::Index>(out.added.size()));
      out.added.push_back(points.positions[point]);
      out.cut_vertices.push_back(slot->second);
    }
    return slot->second;
  };
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    std::array<int, 3> triangle;
    for (int k = 0; k < 3; ++k) {
      triangle[k] = vertex_of(t, k);
      if (triangles[t].cap) out.cut_vertices.push_back(triangle[k]);
    }
    out.triangles.push_back(triangle);
    out.cap_triangles += triangles[t].cap ? 1 : 0;
  }
  return true;
}

}  // namespace altfem::surface_cut
