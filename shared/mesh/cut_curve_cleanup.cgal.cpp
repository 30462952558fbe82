#include "shared/mesh/cut_curve_cleanup.hpp"

#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Geometry>
#include <optional>
#include <utility>
#include <vector>

namespace altfem::cut_curve {

namespace {

// Collapses `edge` keeping the place and "v:input" of `kept_end`, one of its ends.
void collapse_onto(Mesh& mesh, Mesh::Edge_index edge, Mesh::Vertex_index kept_end) {
  auto input_of = mesh.property_map<Mesh::Vertex_index, int>("v:input").first;
  const Point place = mesh.point(kept_end);
  const int input = input_of[kept_end];
  const Mesh::Vertex_index kept = CGAL::Euler::collapse_edge(edge, mesh);
  mesh.point(kept) = place;
  input_of[kept] = input;
}

// The normal of face f (not unit), with `moved` placed at `place`.
Eigen::Vector3d face_normal(const Mesh& mesh, Mesh::Face_index f, Mesh::Vertex_index moved, const Point& place) {
  Eigen::Vector3d corners[3];
  int k = 0;
  for (const Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
    corners[k++] = vector_of(v == moved ? place : mesh.point(v));
  return (corners[1] - corners[0]).cross(corners[2] - corners[0]);
}

// Why the curve's points multiplied: each cut crosses the caps of the earlier ones near the
// pencil's tip, every edge of their triangulation adding a point, and a cap's remeshing
// keeps its border, so a dense curve made a dense cap for the next cut to cross: the cap
// triangles grew by a third per cut. Points inside a flat region carry no shape.
bool collapse_flat_curve_point(Mesh& mesh, Mesh::Vertex_index v,
                               const std::function<bool(Mesh::Vertex_index)>& on_plane, double longest) {
  const auto is_cap = [&](Mesh::Face_index f) {
    for (const Mesh::Vertex_index corner : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      if (!on_plane(corner)) return false;
    return true;
  };
  std::vector<Mesh::Halfedge_index> along_curve;  // from v to its neighbours on the curve
  std::optional<Eigen::Vector3d> flat;            // the unit normal of the faces off the cap
  for (const Mesh::Halfedge_index in : CGAL::halfedges_around_target(mesh.halfedge(v), mesh)) {
    const Mesh::Halfedge_index out = mesh.opposite(in);
    if (mesh.is_border(in) || mesh.is_border(out)) return false;
    const bool cap_before = is_cap(mesh.face(in)), cap_after = is_cap(mesh.face(out));
    if (cap_before != cap_after) along_curve.push_back(out);
    if (cap_before) continue;
    const Eigen::Vector3d normal = face_normal(mesh, mesh.face(in), v, mesh.point(v));
    if (normal.norm() == 0) return false;
    if (!flat) flat = normal.normalized();
    // Faces of one plane: their normals agree to rounding (an earlier cap's corners are
    // rounded constructions on its plane).
    else if (flat->cross(normal.normalized()).norm() > 1e-8 || flat->dot(normal) < 0) return false;
  }
  if (along_curve.size() != 2 || !flat) return false;
  for (const Mesh::Halfedge_index toward : along_curve) {
    const Mesh::Edge_index edge = mesh.edge(toward);
    if (!CGAL::Euler::does_satisfy_link_condition(edge, mesh)) continue;
    const Mesh::Vertex_index neighbour = mesh.target(toward);
    bool refused = false;
    for (const Mesh::Vertex_index other : CGAL::vertices_around_target(mesh.halfedge(v), mesh))
      refused = refused || CGAL::squared_distance(mesh.point(other), mesh.point(neighbour)) > longest * longest;
    for (const Mesh::Face_index f : CGAL::faces_around_target(mesh.halfedge(v), mesh)) {
      if (f == mesh.face(toward) || f == mesh.face(mesh.opposite(toward))) continue;
      const Eigen::Vector3d before = face_normal(mesh, f, v, mesh.point(v));
      const Eigen::Vector3d after = face_normal(mesh, f, v, mesh.point(neighbour));
      // Nor may a face turn over or become a sliver: three points of the curve, which rounding leaves a hair off
      // one line, would make a face that crosses its neighbours.
      refused = refused || after.dot(before) <= 0 || after.norm() <= 1e-6 * longest * longest;
    }
    if (refused) continue;
    collapse_onto(mesh, edge, neighbour);
    return true;
  }
  return false;
}

// One sweep of tangential relaxation over the cap's inner vertices, as CGAL's isotropic
// remeshing relaxes (each to the mean of its neighbours, all moves computed first, a move
// undone where a face around it would turn over), without its vertex normals: CGAL 5.5's
// PMP::tangential_relaxation computes those of the whole mesh at every sweep, a whole side
// of the pencil for a cap of a few dozen faces. The cap is planar, so the mean of its
// neighbours stays in its plane. cap_faces: the faces `cap` marks.
template <typename CapMap, typename BorderMap>
void relax_cap(Mesh& mesh, const std::vector<Mesh::Face_index>& cap_faces, const CapMap& cap, const BorderMap& border) {
  std::vector<std::pair<Mesh::Vertex_index, Point>> moves;
  std::vector<char> seen(mesh.number_of_vertices() + mesh.number_of_removed_vertices(), 0);
  for (const Mesh::Face_index f : cap_faces) {
    for (const Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      if (std::exchange(seen[v.idx()], 1)) continue;
      bool inner = true;
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      int neighbours = 0;
      for (const Mesh::Halfedge_index h : CGAL::halfedges_around_target(mesh.halfedge(v), mesh)) {
        inner = inner && !mesh.is_border(h) && !mesh.is_border(mesh.opposite(h)) && !border[mesh.edge(h)] &&
                cap[mesh.face(h)];
        sum += vector_of(mesh.point(mesh.source(h)));
        ++neighbours;
      }
      if (inner) moves.emplace_back(v, point_of(sum / neighbours));
    }
  }
  for (const auto& [v, place] : moves) {
    bool turns = false;
    for (const Mesh::Face_index f : CGAL::faces_around_target(mesh.halfedge(v), mesh))
      turns = turns || face_normal(mesh, f, v, place).dot(face_normal(mesh, f, v, mesh.point(v))) <= 0;
    if (!turns) mesh.point(v) = place;
  }
}

}  // namespace

void clean(Mesh& mesh, const std::function<bool(Mesh::Vertex_index)>& on_plane, double longest) {
  const auto input_of = mesh.property_map<Mesh::Vertex_index, int>("v:input").first;
  for (bool collapsed = true; collapsed;) {
    collapsed = false;
    std::vector<Mesh::Vertex_index> points;
    for (const Mesh::Vertex_index v : mesh.vertices())
      if (input_of[v] < 0) points.push_back(v);
    for (const Mesh::Vertex_index v : points)
      if (!mesh.is_removed(v)) collapsed = collapse_flat_curve_point(mesh, v, on_plane, longest) || collapsed;
  }
  mesh.collect_garbage();
}

void remesh_cap(Mesh& mesh, const std::function<bool(Mesh::Face_index)>& in_cap, double length) {
  // The cap's faces carry 1: the remeshing hands the mark on to the faces it makes.
  auto cap = mesh.add_property_map<Mesh::Face_index, int>("f:cap", 0).first;
  bool any = false;
  for (const Mesh::Face_index f : mesh.faces()) {
    cap[f] = in_cap(f) ? 1 : 0;
    any = any || cap[f];
  }
  if (any) {
    auto border = mesh.add_property_map<Mesh::Edge_index, bool>("e:cap_border", false).first;
    const auto capped = [&](Mesh::Halfedge_index h) { return !mesh.is_border(h) && cap[mesh.face(h)]; };
    for (const Mesh::Edge_index e : mesh.edges())
      border[e] = capped(mesh.halfedge(e)) != capped(mesh.opposite(mesh.halfedge(e)));
    // CGAL's three iterations without its relaxation (a remesher's set-up touches every
    // halfedge of the mesh: once), then three sweeps of relax_cap.
    std::vector<Mesh::Face_index> cap_faces;
    for (const Mesh::Face_index f : mesh.faces())
      if (cap[f]) cap_faces.push_back(f);
    CGAL::Polygon_mesh_processing::isotropic_remeshing(cap_faces, length, mesh,
                                                       CGAL::parameters::edge_is_constrained_map(border)
                                                           .protect_constraints(true)
                                                           .number_of_iterations(3)
                                                           .number_of_relaxation_steps(0)
                                                           .face_patch_map(cap));
    cap_faces.clear();
    for (const Mesh::Face_index f : mesh.faces())
      if (cap[f]) cap_faces.push_back(f);
    for (int sweep = 0; sweep < 3; ++sweep) relax_cap(mesh, cap_faces, cap, border);
    mesh.remove_property_map(border);
  }
  mesh.remove_property_map(cap);
  mesh.collect_garbage();
}

}  // namespace altfem::cut_curve
