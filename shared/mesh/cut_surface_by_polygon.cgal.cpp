#include <CGAL/Polygon_mesh_processing/clip.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <functional>
#include <map>
#include <set>

#include "shared/mesh/cut_by_surface.hpp"
#include "shared/mesh/cut_surface_pieces.hpp"

namespace altfem::surface_cut {

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

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;

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

// A surface blade's triangles as a CGAL mesh.
Mesh surface_blade_mesh(const SurfaceBlade& blade) {
  Mesh mesh;
  std::vector<Mesh::Vertex_index> vertices;
  for (Eigen::Index v = 0; v < blade.vertices.rows(); ++v)
    vertices.push_back(mesh.add_vertex(point_of(blade.vertices.row(v).transpose())));
  for (Eigen::Index t = 0; t < blade.triangles.rows(); ++t)
    mesh.add_face(vertices[blade.triangles(t, 0)], vertices[blade.triangles(t, 1)], vertices[blade.triangles(t, 2)]);
  return mesh;
}

// Bit patterns of a point, for finding the surface's copies of a cap vertex: both are
// the same exact intersection of a surface edge with a blade triangle, rounded once.
using PointKey = std::array<double, 3>;
PointKey key_of(const Point& p) { return {p.x(), p.y(), p.z()}; }

// The plane a cap's face lies in: a polygon blade's, or (a surface blade's cap, whose faces
// are parts of its triangles) the face's own.
using CapPlane = std::function<CuttingPlane(std::size_t cap, const Mesh& mesh, Mesh::Face_index face)>;

// `piece` split by `splitter` (its vertices on the cut curves duplicated, one copy per
// side) and each of `caps` clipped to the body, appended to `out` with a copy of each cap
// per side. A bent cap (a surface blade's) keeps its triangles and may miss the piece: then
// this returns false, appending nothing. One wholly inside the piece leaves the piece's
// triangles as they are and adds its two sides (its border, a crack's rim, one vertex).
bool cut_piece_by_caps(Mesh& piece, Mesh splitter, std::vector<Mesh> caps, const CapPlane& plane_of,
                       const std::vector<bool>& planar, double edge_length, CutPieces& out) {
  Mesh clipper = piece;  // the body before the split, for the caps (clip leaves it as it is)
  const std::size_t vertices_before = piece.number_of_vertices();
  PMP::split(piece, splitter);
  piece.collect_garbage();
  const bool split_any = piece.number_of_vertices() != vertices_before;
  // Coplanar pieces of the blade and the surface can leave polygons: triangles again.
  PMP::triangulate_faces(piece);
  renumber_by_position(piece);
  for (std::size_t b = 0; b < caps.size(); ++b) {
    Mesh& cap = caps[b];
    PMP::clip(cap, clipper, CGAL::parameters::clip_volume(false), CGAL::parameters::do_not_modify(true));
    cap.collect_garbage();
    PMP::triangulate_faces(cap);
    renumber_by_position(cap);
    // A planar cap is remeshed in its plane; a bent one keeps the blade's triangles.
    if (planar[b])
      cut_curve::remesh_cap(
          cap, [](Mesh::Face_index) { return true; }, edge_length);
  }
  // A bent cap that does not cross the surface may still lie inside the body (a closed
  // blade, a crack wholly inside): the surface is left as it is, and gains the cap's two sides.
  if (std::none_of(planar.begin(), planar.end(), [](bool flat) { return flat; }) && !split_any &&
      std::all_of(caps.begin(), caps.end(), [](const Mesh& cap) { return cap.number_of_faces() == 0; }))
    return false;

  // The piece's vertices: the input's, then its new ones (the curve's copies).
  std::vector<int> output_vertex(piece.number_of_vertices() + piece.number_of_removed_vertices(), -1);
  const auto input_of = piece.property_map<Mesh::Vertex_index, int>("v:input").first;
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
  // Every point of the split piece with its copies (two on a cut curve).
  std::map<PointKey, std::vector<std::pair<int, Mesh::Vertex_index>>> copies_at;
  for (const Mesh::Vertex_index v : piece.vertices())
    copies_at[key_of(piece.point(v))].push_back({output_vertex[v.idx()], v});
  // The signed distance to the blade's plane of the piece vertex's farthest neighbour: a
  // curve's own points are constructions a rounding off the plane, the neighbours off the
  // curve are clearly on their copy's side.
  const auto farthest = [&](Mesh::Vertex_index v, const CuttingPlane& blade) {
    const Eigen::Vector3d unit_normal = blade.normal.normalized();
    double result = 0;
    for (const Mesh::Vertex_index neighbour : CGAL::vertices_around_target(piece.halfedge(v), piece)) {
      const double distance = unit_normal.dot(vector_of(piece.point(neighbour)) - blade.point);
      if (std::abs(distance) > std::abs(result)) result = distance;
    }
    return result;
  };
  // A cap vertex is the piece's copy on the cap's side; else a point inside the body: on
  // the cap's border (a finite blade's edge there) one vertex for both caps, since the
  // blade stops there, and inside the cap (its remeshing's) one per side, so that the two
  // caps part.
  std::map<std::pair<PointKey, int>, int> inside;
  // The cap's point of a curve is the piece's, but for rounding: both are one exact
  // intersection, which corefinement constructs from other operands for the cap (the
  // blade's triangle against the piece) than for the piece (its edge, perhaps cut by
  // another blade first) — a unit in the last place apart, seen with a tilted blade.
  const double same_point = 1e-12 * 40 * edge_length;  // of the piece's diagonal
  const auto copies_of = [&](const Point& p, bool on_border) {
    const auto found = copies_at.find(key_of(p));
    if (found != copies_at.end() || !on_border) return found;  // a cut's point is on the cap's border
    for (auto curve = copies_at.begin(); curve != copies_at.end(); ++curve)
      if ((curve->second.size() > 1 || curve->second.front().first >= out.input_count) &&  // the cut's points
          (Eigen::Vector3d(curve->first[0], curve->first[1], curve->first[2]) - vector_of(p)).norm() <= same_point)
        return curve;
    return copies_at.end();
  };
  const auto cap_vertex = [&](const Mesh& cap, Mesh::Vertex_index v, const CuttingPlane& plane, int side) {
    const Point& p = cap.point(v);
    const bool on_border = cap.is_border(v);
    if (const auto found = copies_of(p, on_border); found != copies_at.end()) {
      const auto& copies = found->second;
      const auto best = std::max_element(copies.begin(), copies.end(), [&](const auto& a, const auto& b) {
        return side * farthest(a.second, plane) < side * farthest(b.second, plane);
      });
      out.cut_vertices.push_back(best->first);
      return best->first;
    }
    const int copy = on_border ? 0 : side;
    const auto [slot, inserted] = inside.try_emplace(
        {key_of(p), copy}, static_cast<int>(out.input_count + static_cast<Eigen::Index>(out.added.size())));
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
  for (std::size_t b = 0; b < caps.size(); ++b)
    for (const int side : {+1, -1})
      for (const Mesh::Face_index f : caps[b].faces()) {
        const CuttingPlane plane = plane_of(b, caps[b], f);
        std::array<int, 3> triangle;
        int k = 0;
        for (const Mesh::Vertex_index v : CGAL::vertices_around_face(caps[b].halfedge(f), caps[b]))
          triangle[k++] = cap_vertex(caps[b], v, plane, side);
        if (side > 0) std::swap(triangle[1], triangle[2]);
        out.triangles.push_back(triangle);
        ++out.cap_triangles;
      }
  return true;
}

}  // namespace

bool cut_piece_by_blades(Mesh& piece, const std::vector<const CuttingPlane*>& blades, double edge_length,
                         CutPieces& out) {
  // Each polygon, clipped to the body, is its cap, remeshed in its plane; a surface blade
  // (one mesh: its reader checked it does not intersect itself) is its cap as it is.
  Mesh splitter;
  std::vector<Mesh> caps;
  std::vector<bool> planar;
  for (const CuttingPlane* blade : blades) {
    planar.push_back(blade->surface == nullptr);
    caps.push_back(planar.back() ? blade_triangles(*blade) : surface_blade_mesh(*blade->surface));
    CGAL::copy_face_graph(caps.back(), splitter);
  }
  // Blades that meet one another (inside the body or beyond it) make the splitter intersect
  // itself, which corefinement does not take: their caps are joined by how they turn.
  if (blades.size() > 1 && PMP::does_self_intersect(splitter))
    return cut_piece_by_meeting_blades(piece, caps, planar, edge_length, out);
  const auto plane_of = [&](std::size_t cap, const Mesh& mesh, Mesh::Face_index face) {
    if (planar[cap]) return *blades[cap];
    std::array<Eigen::Vector3d, 3> corners;
    int k = 0;
    for (const Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(face), mesh))
      corners[k++] = vector_of(mesh.point(v));
    return CuttingPlane(corners[0], (corners[1] - corners[0]).cross(corners[2] - corners[0]));
  };
  return cut_piece_by_caps(piece, splitter, std::move(caps), plane_of, planar, edge_length, out);
}

}  // namespace altfem::surface_cut
