#include <CGAL/Polygon_mesh_processing/clip.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <set>

#include "shared/mesh/cut_curve_cleanup.hpp"
#include "shared/mesh/cut_surface.hpp"
#include "shared/mesh/mesh_components.hpp"
#include "shared/mesh/split_surface_by_plane.hpp"

namespace altfem {

namespace {

using Kernel = cut_curve::Kernel;
using Point = cut_curve::Point;
using Mesh = cut_curve::Mesh;
namespace PMP = CGAL::Polygon_mesh_processing;

Point point_of(const Eigen::Vector3d& x) { return {x.x(), x.y(), x.z()}; }
Eigen::Vector3d vector_of(const Point& p) { return {p.x(), p.y(), p.z()}; }

// The volume the closed `mesh` encloses, its tetrahedra from its first vertex (not the
// origin, which would cancel a small piece's volume away).
double enclosed_volume(const Mesh& mesh) {
  const Eigen::Vector3d apex = vector_of(mesh.point(*mesh.vertices().begin()));
  double volume = 0;
  for (const Mesh::Face_index f : mesh.faces()) {
    std::array<Eigen::Vector3d, 3> corner;
    int k = 0;
    for (const Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      corner[k++] = vector_of(mesh.point(v)) - apex;
    volume += corner[0].dot(corner[1].cross(corner[2])) / 6;
  }
  return volume;
}

// A finite blade's polygon as triangles, a fan turning counter-clockwise about its normal.
Mesh blade_triangles(const CuttingPlane& blade) {
  const Eigen::Vector3d normal = blade.normal.normalized();
  std::vector<Eigen::Vector3d> corners = blade.polygon;
  Eigen::Vector3d newell = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < corners.size(); ++k) newell += corners[k].cross(corners[(k + 1) % corners.size()]);
  if (newell.dot(normal) < 0) std::reverse(corners.begin(), corners.end());
  Mesh mesh;
  std::vector<Mesh::Vertex_index> vertices;
  for (const Eigen::Vector3d& corner : corners) vertices.push_back(mesh.add_vertex(point_of(corner)));
  for (std::size_t k = 1; k + 1 < vertices.size(); ++k) mesh.add_face(vertices[0], vertices[k], vertices[k + 1]);
  return mesh;
}

// Bit patterns of a point, for finding the surface's copies of a cap vertex: both are
// the same exact intersection of a surface edge with a blade triangle, rounded once.
using PointKey = std::array<double, 3>;
PointKey key_of(const Point& p) { return {p.x(), p.y(), p.z()}; }

// Angle-weighted normals of the vertices of `surface` that `marked` holds.
Eigen::MatrixXd vertex_normals(const SurfaceMesh& surface, const std::vector<char>& marked) {
  Eigen::MatrixXd normals = Eigen::MatrixXd::Zero(surface.vertices.rows(), 3);
  for (Eigen::Index t = 0; t < surface.triangles.rows(); ++t) {
    const Eigen::Vector3d p[3] = {surface.vertices.row(surface.triangles(t, 0)),
                                  surface.vertices.row(surface.triangles(t, 1)),
                                  surface.vertices.row(surface.triangles(t, 2))};
    const Eigen::Vector3d normal = (p[1] - p[0]).cross(p[2] - p[0]);
    if (normal.norm() == 0) continue;
    for (int k = 0; k < 3; ++k) {
      const int vertex = surface.triangles(t, k);
      if (!marked[vertex]) continue;
      const Eigen::Vector3d u = p[(k + 1) % 3] - p[k], v = p[(k + 2) % 3] - p[k];
      normals.row(vertex) += std::atan2(u.cross(v).norm(), u.dot(v)) * normal.normalized().transpose();
    }
  }
  return normals;
}

// What cutting the pieces adds to the surface: vertices after the input's, triangles in
// the output's numbering, the vertices on the cut.
struct CutPieces {
  Eigen::Index input_count = 0;
  std::vector<Eigen::Vector3d> added;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> cut_vertices;
  int cap_triangles = 0;
};

// CGAL's corefinement numbers the vertices and faces it makes in an order that follows
// heap addresses, which differ from run to run, and the cap's remeshing depends on that
// order: the same cut gave surfaces that differed in a few vertices from run to run.
// Renumbered by position (copies of a point on the cut curve by their neighbours), and the
// faces by their renumbered vertices, the same cut gives the same surface every run.
void renumber_by_position(Mesh& mesh) {
  const auto [input_of, has_input] = mesh.property_map<Mesh::Vertex_index, int>("v:input");
  using Key = std::array<double, 7>;
  std::vector<std::pair<Key, Mesh::Vertex_index>> keyed;
  for (const Mesh::Vertex_index v : mesh.vertices()) {
    Eigen::Vector3d ring = Eigen::Vector3d::Zero();
    if (!mesh.is_isolated(v))
      for (const Mesh::Vertex_index neighbour : CGAL::vertices_around_target(mesh.halfedge(v), mesh))
        ring += vector_of(mesh.point(neighbour));
    const Point& p = mesh.point(v);
    keyed.push_back({{p.x(), p.y(), p.z(), has_input ? double(input_of[v]) : 0.0, ring.x(), ring.y(), ring.z()}, v});
  }
  std::sort(keyed.begin(), keyed.end());
  Mesh sorted;
  sorted.set_recycle_garbage(false);
  auto sorted_input = sorted.add_property_map<Mesh::Vertex_index, int>("v:input", -1).first;
  std::vector<Mesh::Vertex_index> renumbered(mesh.number_of_vertices() + mesh.number_of_removed_vertices());
  for (const auto& [key, v] : keyed) {
    renumbered[v.idx()] = sorted.add_vertex(mesh.point(v));
    if (has_input) sorted_input[renumbered[v.idx()]] = input_of[v];
  }
  std::vector<std::array<Mesh::Vertex_index, 3>> faces;
  for (const Mesh::Face_index f : mesh.faces()) {
    std::array<Mesh::Vertex_index, 3> corners;
    int k = 0;
    for (const Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      corners[k++] = renumbered[v.idx()];
    // The lowest corner first keeps the face's orientation.
    std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
    faces.push_back(corners);
  }
  std::sort(faces.begin(), faces.end());
  for (const auto& corners : faces) sorted.add_face(corners[0], corners[1], corners[2]);
  if (!has_input) sorted.remove_property_map(sorted_input);
  mesh = std::move(sorted);
}

// The faces of `mesh` that `in_cap` selects, remeshed to edges of about `length` with their
// border kept: a cap triangulated from its boundary alone has long edges across it, which
// the next cut crosses one by one, so that the points of the cut curve multiply with
// every cut through the same place.
template <class InCap>
void remesh_cap(Mesh& mesh, const InCap& in_cap, double length) {
  std::vector<Mesh::Face_index> cap_faces;
  for (const Mesh::Face_index f : mesh.faces())
    if (in_cap(f)) cap_faces.push_back(f);
  if (cap_faces.empty()) return;
  auto border = mesh.add_property_map<Mesh::Edge_index, bool>("e:cap_border", false).first;
  const auto capped = [&](Mesh::Halfedge_index h) { return !mesh.is_border(h) && in_cap(mesh.face(h)); };
  for (const Mesh::Edge_index e : mesh.edges())
    border[e] = capped(mesh.halfedge(e)) != capped(mesh.opposite(mesh.halfedge(e)));
  PMP::isotropic_remeshing(
      cap_faces, length, mesh,
      CGAL::parameters::edge_is_constrained_map(border).protect_constraints(true).number_of_iterations(3));
  mesh.remove_property_map(border);
  mesh.collect_garbage();
}

// What the whole-plane split cannot close into two manifold sides (border loops that cross
// or meet after rounding): the piece is left whole, counted, and the next blade tries it.
struct UnsplitPiece : std::runtime_error {
  UnsplitPiece() : std::runtime_error("the plane's sides of the piece do not close") {}
};

// The closed `piece` cut by the whole plane of `blade` (split_surface_by_plane: its sides
// exact predicates, each crossing point rounded once for both sides), each side's cut
// curve cleaned and its cap remeshed. A vertex of the input that both sides keep (on the
// plane) gets a copy for the positive side. Appends both sides to `out`.
bool cut_piece_by_plane(const Mesh& piece, const ExactBlade& exact, double edge_length, CutPieces& out) {
  auto split = split_surface_by_plane(piece, exact, 1e-9 * edge_length);
  if (!split) throw UnsplitPiece();
  if (split->grazes) return false;
  // New points (input −1) and the input's on the plane: the cut curve and the cap.
  const auto on_plane_in = [&](const Mesh& half) {
    return
        [&half, &split, input_of = half.property_map<Mesh::Vertex_index, int>("v:input").first](Mesh::Vertex_index v) {
          return input_of[v] < 0 ||
                 std::binary_search(split->inputs_on_plane.begin(), split->inputs_on_plane.end(), input_of[v]);
        };
  };
  std::array<double, 2> volumes{};
  for (int side = 0; side < 2; ++side) {
    Mesh& half = split->sides[side];
    const auto on_plane = on_plane_in(half);
    cut_curve::clean(half, on_plane, 0.0, 4.0 / 3 * edge_length);
    // Remeshed: the cap where it lies in the plane. Not around a vertex taken on it within
    // the snap: each side remeshes its own cap, and where the caps are not flat they would
    // part and the sides' volumes no longer sum to the piece's.
    const auto input_of = half.property_map<Mesh::Vertex_index, int>("v:input").first;
    remesh_cap(
        half,
        [&](Mesh::Face_index f) {
          for (const Mesh::Vertex_index v : CGAL::vertices_around_face(half.halfedge(f), half))
            if (input_of[v] >= 0 && exact.side(vector_of(half.point(v))) != 0) return false;
          return true;
        },
        edge_length);
    volumes[side] = enclosed_volume(half);
  }
  // A plane that grazes the piece (a chip far below the sliver rule, which the clean-up's
  // collapses flatten) opens nothing.
  if (std::min(volumes[0], volumes[1]) <= 1e-12 * (volumes[0] + volumes[1])) return false;
  std::set<int> used;
  for (Mesh& half : split->sides) {
    const auto input_of = half.property_map<Mesh::Vertex_index, int>("v:input").first;
    const auto on_plane = on_plane_in(half);
    std::vector<int> output_vertex(half.number_of_vertices() + half.number_of_removed_vertices(), -1);
    std::vector<char> on_curve(output_vertex.size(), 0);
    for (const Mesh::Vertex_index v : half.vertices()) {
      const std::size_t k = v.idx();
      const int input = input_of[v];
      on_curve[k] = on_plane(v);
      if (input >= 0 && used.insert(input).second) {
        output_vertex[k] = input;
      } else {
        output_vertex[k] = static_cast<int>(out.input_count + static_cast<Eigen::Index>(out.added.size()));
        out.added.push_back(vector_of(half.point(v)));
      }
      if (on_curve[k]) out.cut_vertices.push_back(output_vertex[k]);
    }
    for (const Mesh::Face_index f : half.faces()) {
      std::array<int, 3> triangle;
      bool cap = true;
      int k = 0;
      for (const Mesh::Vertex_index v : CGAL::vertices_around_face(half.halfedge(f), half)) {
        triangle[k++] = output_vertex[v.idx()];
        cap = cap && on_curve[v.idx()];
      }
      out.triangles.push_back(triangle);
      out.cap_triangles += cap;
    }
  }
  return true;
}

// Whether the blade's plane has vertices of the piece made of `triangles` strictly on both
// sides: only then does it open the piece; one through a face or a vertex of it (and its
// plane through nothing else) separates nothing.
bool separates(const SurfaceMesh& surface, const std::vector<int>& triangles, const ExactBlade& exact) {
  bool below = false, above = false;
  for (const int t : triangles)
    for (int k = 0; k < 3; ++k) {
      const int side = exact.side(surface.vertices.row(surface.triangles(t, k)));
      below = below || side < 0;
      above = above || side > 0;
    }
  return below && above;
}

// What neither the plane's split nor corefinement can cut: a piece whose earlier caps lie
// on one another (a notch) or cross its sides. It stays so, since no later cut changes a piece it leaves whole.
struct SelfIntersectingPiece : std::runtime_error {
  SelfIntersectingPiece() : std::runtime_error("the piece intersects itself") {}
};

// Cuts the closed piece made of `triangles` of `surface`, which the blade separates, and
// appends it to `out`; false, appending nothing, when the blade only grazes it.
bool cut_piece(const SurfaceMesh& surface, const std::vector<int>& triangles, const CuttingPlane& blade,
               const ExactBlade& exact, CutPieces& out) {
  // The piece as a CGAL mesh, each vertex with its index in the input ("v:input", −1 for
  // the vertices a cut adds), which CGAL carries through its operations.
  Mesh piece;
  auto input_of = piece.add_property_map<Mesh::Vertex_index, int>("v:input", -1).first;
  // A recycled slot would keep the removed vertex's "v:input": new vertices go at the end.
  piece.set_recycle_garbage(false);
  std::map<int, int> piece_vertex;
  Eigen::AlignedBox3d bounds;
  for (const int t : triangles) {
    std::array<Mesh::Vertex_index, 3> corners;
    for (int k = 0; k < 3; ++k) {
      const int v = surface.triangles(t, k);
      const auto [slot, inserted] = piece_vertex.try_emplace(v, static_cast<int>(piece.number_of_vertices()));
      if (inserted) {
        input_of[piece.add_vertex(point_of(surface.vertices.row(v)))] = v;
        bounds.extend(Eigen::Vector3d(surface.vertices.row(v)));
      }
      corners[k] = Mesh::Vertex_index(static_cast<Mesh::size_type>(slot->second));
    }
    piece.add_face(corners[0], corners[1], corners[2]);
  }
  // The precondition of the split and of corefinement: a piece that intersects itself is
  // left whole rather than cut into garbage.
  if (PMP::does_self_intersect(piece)) throw SelfIntersectingPiece();
  // The caps' edges: a 40th of the piece's diagonal, as a shape's surface is tessellated
  // (SceneGeometry::shape_surface). Not the piece's own edges: those a cut leaves short
  // would shrink the caps of every cut after it.
  const double edge_length = bounds.diagonal().norm() / 40;
  if (blade.polygon.empty()) return cut_piece_by_plane(piece, exact, edge_length, out);

  // The piece split along the curve where the blade crosses it (its vertices there
  // duplicated, one copy per side), and the blade clipped to the body: the cap.
  Mesh splitter = blade_triangles(blade);
  Mesh cap = splitter;
  Mesh clipper = piece;
  PMP::split(piece, splitter);
  PMP::clip(cap, clipper, CGAL::parameters::clip_volume(false), CGAL::parameters::do_not_modify(true));
  piece.collect_garbage();
  cap.collect_garbage();
  // Coplanar pieces of the blade and the surface can leave polygons: triangles again.
  PMP::triangulate_faces(piece);
  PMP::triangulate_faces(cap);
  renumber_by_position(piece);
  renumber_by_position(cap);
  remesh_cap(
      cap, [](Mesh::Face_index) { return true; }, edge_length);

  // The piece's vertices: the input's, then its new ones (the curve's copies).
  std::vector<int> output_vertex(piece.number_of_vertices() + piece.number_of_removed_vertices(), -1);
  input_of = piece.property_map<Mesh::Vertex_index, int>("v:input").first;
  std::set<int> used;
  for (const Mesh::Vertex_index v : piece.vertices()) {
    const std::size_t k = v.idx();
    if (input_of[v] >= 0 && used.insert(input_of[v]).second) {
      output_vertex[k] = input_of[v];
    } else {
      output_vertex[k] = static_cast<int>(out.input_count + static_cast<Eigen::Index>(out.added.size()));
      out.added.push_back(vector_of(piece.point(v)));
      out.cut_vertices.push_back(output_vertex[k]);
    }
  }
  // Every point of the split piece with its copies (two on the cut curve), each with the
  // signed distance to the blade's plane of its farthest neighbour: the curve's own points
  // are constructions a rounding off the plane, the neighbours off the curve are clearly
  // on their copy's side.
  const Eigen::Vector3d unit_normal = blade.normal.normalized();
  std::map<PointKey, std::vector<std::pair<int, double>>> copies_at;
  for (const Mesh::Vertex_index v : piece.vertices()) {
    double farthest = 0;
    for (const Mesh::Vertex_index neighbour : CGAL::vertices_around_target(piece.halfedge(v), piece)) {
      const double distance = unit_normal.dot(vector_of(piece.point(neighbour)) - blade.point);
      if (std::abs(distance) > std::abs(farthest)) farthest = distance;
    }
    copies_at[key_of(piece.point(v))].push_back({output_vertex[v.idx()], farthest});
  }
  // A cap vertex is the piece's copy on the cap's side, or a point inside the body (on a
  // finite blade's edge there), one vertex for both caps: the blade stops there.
  std::map<PointKey, int> inside;
  const auto cap_vertex = [&](const Point& p, int side) {
    if (const auto found = copies_at.find(key_of(p)); found != copies_at.end()) {
      const auto& copies = found->second;
      const auto best = std::max_element(copies.begin(), copies.end(), [&](const auto& a, const auto& b) {
        return side * a.second < side * b.second;
      });
      out.cut_vertices.push_back(best->first);
      return best->first;
    }
    const auto [slot, inserted] =
        inside.try_emplace(key_of(p), static_cast<int>(out.input_count + static_cast<Eigen::Index>(out.added.size())));
    if (inserted) {
      out.added.push_back(vector_of(p));
      out.cut_vertices.push_back(slot->second);
    }
    return slot->second;
  };

  for (const Mesh::Face_index f : piece.faces()) {
    std::array<int, 3> triangle;
    int k = 0;
    for (const Mesh::Vertex_index v : CGAL::vertices_around_face(piece.halfedge(f), piece))
      triangle[k++] = output_vertex[v.idx()];
    out.triangles.push_back(triangle);
  }
  // A cap per side, facing away from its side's material: the blade's fan turns about its
  // normal, so the positive side's cap is turned over.
  for (const int side : {+1, -1})
    for (const Mesh::Face_index f : cap.faces()) {
      std::array<int, 3> triangle;
      int k = 0;
      for (const Mesh::Vertex_index v : CGAL::vertices_around_face(cap.halfedge(f), cap))
        triangle[k++] = cap_vertex(cap.point(v), side);
      if (side > 0) std::swap(triangle[1], triangle[2]);
      out.triangles.push_back(triangle);
      ++out.cap_triangles;
    }
  return true;
}

}  // namespace

SurfaceCut cut_surface(const SurfaceMesh& surface, const CuttingPlane& blade) {
  const ExactBlade exact(blade);
  const std::vector<int> piece_of = surface_vertex_pieces(surface);
  std::map<int, std::vector<int>> triangles_of;
  for (Eigen::Index t = 0; t < surface.triangles.rows(); ++t)
    triangles_of[piece_of[surface.triangles(t, 0)]].push_back(static_cast<int>(t));
  std::optional<int> only;
  if (blade.piece_at) {
    Eigen::Index nearest = 0;
    (surface.vertices.rowwise() - blade.piece_at->transpose()).rowwise().squaredNorm().minCoeff(&nearest);
    only = piece_of[nearest];
  }

  CutPieces cut;
  cut.input_count = surface.vertices.rows();
  const bool marks_apply = surface.self_intersecting.size() == static_cast<std::size_t>(surface.triangles.rows());
  std::vector<char> self_intersecting;  // per output triangle
  std::vector<int> pieces_intersecting_themselves;
  int left_whole = 0;
  for (const auto& [piece, triangles] : triangles_of) {
    bool opened = false, grazed = false,
         intersects_itself = marks_apply && surface.self_intersecting[triangles.front()];
    if ((!only || *only == piece) && separates(surface, triangles, exact)) {
      // A piece an earlier cut made intersect itself is left whole (counted) rather than
      // failing the run; it is found once, when the cut after the one that made it so
      // tries it, and remembered in the surface.
      if (!intersects_itself) {
        try {
          opened = cut_piece(surface, triangles, blade, exact, cut);
          grazed = !opened;
        } catch (const SelfIntersectingPiece&) {
          intersects_itself = true;
        } catch (const std::exception&) {
          // Another refusal (corefinement's, or a split whose sides do not close) is this
          // blade's: the next one tries again.
        }
      }
      left_whole += !opened && !grazed;
    }
    if (!opened)
      for (const int t : triangles)
        cut.triangles.push_back({surface.triangles(t, 0), surface.triangles(t, 1), surface.triangles(t, 2)});
    self_intersecting.resize(cut.triangles.size(), intersects_itself);
    if (intersects_itself) pieces_intersecting_themselves.push_back(piece);
  }

  SurfaceCut result;
  result.facts = {{"added_triangles", static_cast<long long>(cut.triangles.size()) - surface.triangles.rows()},
                  {"cap_triangles", cut.cap_triangles},
                  {"added_vertices", static_cast<long long>(cut.added.size())},
                  {"pieces_left_whole", left_whole}};
  if (cut.cap_triangles == 0) {
    result.surface = surface;
    if (!pieces_intersecting_themselves.empty()) {
      std::vector<char>& flags = result.surface.self_intersecting;
      flags.assign(static_cast<std::size_t>(surface.triangles.rows()), 0);
      for (const int piece : pieces_intersecting_themselves)
        for (const int t : triangles_of[piece]) flags[t] = 1;
    }
    return result;
  }
  SurfaceMesh& out = result.surface;
  out.vertices.resize(cut.input_count + static_cast<Eigen::Index>(cut.added.size()), 3);
  out.vertices.topRows(cut.input_count) = surface.vertices;
  for (std::size_t k = 0; k < cut.added.size(); ++k)
    out.vertices.row(cut.input_count + static_cast<Eigen::Index>(k)) = cut.added[k];
  out.triangles.resize(static_cast<Eigen::Index>(cut.triangles.size()), 3);
  for (std::size_t t = 0; t < cut.triangles.size(); ++t)
    out.triangles.row(static_cast<Eigen::Index>(t)) << cut.triangles[t][0], cut.triangles[t][1], cut.triangles[t][2];
  if (!pieces_intersecting_themselves.empty()) out.self_intersecting = std::move(self_intersecting);

  // The vertices of this cut and of earlier ones read their field a hair inside the
  // material they bound: against their angle-weighted normal, by 1e-7 of the body's size.
  std::vector<char> on_cut(static_cast<std::size_t>(out.vertices.rows()), 0);
  for (const int vertex : cut.cut_vertices) on_cut[vertex] = 1;
  if (surface.embedding_offsets.size() != 0)
    for (Eigen::Index v = 0; v < cut.input_count; ++v)
      if (!surface.embedding_offsets.row(v).isZero()) on_cut[v] = 1;
  const Eigen::MatrixXd normals = vertex_normals(out, on_cut);
  Eigen::AlignedBox3d bounds;
  for (Eigen::Index v = 0; v < out.vertices.rows(); ++v) bounds.extend(Eigen::Vector3d(out.vertices.row(v)));
  const double hair = 1e-7 * bounds.diagonal().norm();
  out.embedding_offsets = Eigen::MatrixXd::Zero(out.vertices.rows(), 3);
  for (Eigen::Index v = 0; v < out.vertices.rows(); ++v) {
    const double length = normals.row(v).norm();
    if (on_cut[v] && length > 1e-6) out.embedding_offsets.row(v) = -hair / length * normals.row(v);
  }
  return result;
}

}  // namespace altfem
