#include <CGAL/Polygon_mesh_processing/self_intersections.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <unordered_map>
#include <utility>

#include "shared/mesh/bounding_box.hpp"
#include "shared/mesh/coplanar_blades.hpp"
#include "shared/mesh/cut_by_surface.hpp"
#include "shared/mesh/cut_surface.hpp"
#include "shared/mesh/cut_surface_pieces.hpp"
#include "shared/mesh/mesh_components.hpp"

namespace altfem {

namespace {

using surface_cut::CutPieces;
using surface_cut::Mesh;
using surface_cut::point_of;
namespace PMP = CGAL::Polygon_mesh_processing;

// Angle-weighted normals of the vertices of `surface` that `marked` holds.
Eigen::MatrixXd vertex_normals(const SurfaceMesh& surface, const std::vector<char>& marked) {
  Eigen::MatrixXd normals = Eigen::MatrixXd::Zero(surface.vertices.rows(), 3);
  for (Eigen::Index t = 0; t < surface.triangles.rows(); ++t) {
    const Eigen::Vector3d p[3] = {surface.vertices.row(surface.triangles(t, 0)),
                                  surface.vertices.row(surface.triangles(t, 1)),
                                  surface.vertices.row(surface.triangles(t, 2))};
    if (!marked[surface.triangles(t, 0)] && !marked[surface.triangles(t, 1)] && !marked[surface.triangles(t, 2)])
      continue;
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

// Whether the polygon of the blade covers the whole section of the piece made of
// `triangles`: every point where its plane crosses an edge, and every vertex in it (the
// section lies in their convex hull, the polygon is convex). Then the polygon is the whole
// plane to the piece.
bool covers_section(const SurfaceMesh& surface, const std::vector<int>& triangles, const ExactBlade& exact) {
  for (const int t : triangles)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d p = surface.vertices.row(surface.triangles(t, k)),
                            q = surface.vertices.row(surface.triangles(t, (k + 1) % 3));
      const int side_p = exact.side(p), side_q = exact.side(q);
      if ((side_p == 0 && !exact.covers(p)) || (side_p * side_q < 0 && !exact.covers_crossing(p, q))) return false;
    }
  return true;
}

// Whether the plane of `blade` has vertices of the piece made of `triangles` on both sides
// farther than split_surface_by_plane takes a vertex on it (1e-9 of the caps' edge, a
// 40th of the piece's diagonal). A piece's side that an earlier cut by the same plane left
// has only the rounding of its cut's points off the plane: that blade grazes it, and is
// not one of its blades — among several blades, and alone too (a notch's blade cut again
// from before it, after a pass that split the pieces whose section it spans, found such a
// half "crossed", and its whole-plane split could not close it).
bool clearly_separates(const SurfaceMesh& surface, const std::vector<int>& triangles, const CuttingPlane& blade) {
  Eigen::AlignedBox3d bounds;
  double below = 0, above = 0;
  const Eigen::Vector3d unit_normal = blade.normal.normalized();
  for (const int t : triangles)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d x = surface.vertices.row(surface.triangles(t, k));
      bounds.extend(x);
      const double distance = unit_normal.dot(x - blade.point);
      below = std::min(below, distance);
      above = std::max(above, distance);
    }
  const double snapped = 1e-9 * bounds.diagonal().norm() / 40;
  return below < -snapped && above > snapped;
}

// Whether the bounding boxes of the piece made of `triangles` and of the blade meet: only
// then may the blade cross the piece (corefinement finds whether it does).
bool meets_bounds(const SurfaceMesh& surface, const std::vector<int>& triangles, const SurfaceBlade& blade) {
  Eigen::AlignedBox3d piece_bounds, blade_bounds;
  for (const int t : triangles)
    for (int k = 0; k < 3; ++k) piece_bounds.extend(Eigen::Vector3d(surface.vertices.row(surface.triangles(t, k))));
  for (Eigen::Index v = 0; v < blade.vertices.rows(); ++v) blade_bounds.extend(Eigen::Vector3d(blade.vertices.row(v)));
  return piece_bounds.intersects(blade_bounds);
}

// What corefinement cannot cut: a piece whose earlier caps lie on one another (a notch) or
// cross its sides. It stays so, since no later cut changes a piece it leaves whole.
struct SelfIntersectingPiece : std::runtime_error {
  SelfIntersectingPiece() : std::runtime_error("the piece intersects itself") {}
};

// What one corefinement cannot cut at once: a piece that several blades cross, one of them
// over its whole section (that one splits it by its plane, then the others cut its sides).
struct NotAtOnce : std::runtime_error {
  NotAtOnce() : std::runtime_error("blades to be applied one after the other") {}
};

// Cuts the closed piece made of `triangles` of `surface`, which the `blades` separate
// (with `exact` theirs), and appends it to `out`; false, appending nothing, when a single
// blade only grazes it. Throws SelfIntersectingPiece for a piece corefinement would have
// to cut and cannot, NotAtOnce as above.
bool cut_piece(const SurfaceMesh& surface, const std::vector<int>& triangles,
               const std::vector<const CuttingPlane*>& blades, const std::vector<const ExactBlade*>& exact,
               bool marked_intersecting, CutPieces& out) {
  // The piece's points in order of first use, each with its index in the input
  // ("v:input"), and its triangles.
  TrianglePiece arrays;
  std::unordered_map<int, int> piece_vertex;
  Eigen::AlignedBox3d bounds;
  for (const int t : triangles) {
    std::array<int, 3> corners{};
    for (int k = 0; k < 3; ++k) {
      const int v = surface.triangles(t, k);
      const auto [slot, inserted] = piece_vertex.try_emplace(v, static_cast<int>(arrays.points.size()));
      if (inserted) {
        arrays.points.push_back(point_of(surface.vertices.row(v)));
        arrays.input.push_back(v);
        bounds.extend(Eigen::Vector3d(surface.vertices.row(v)));
      }
      corners[k] = slot->second;
    }
    arrays.triangles.push_back(corners);
  }
  // The caps' edges: a 40th of the piece's diagonal, as a shape's surface is tessellated
  // (SceneGeometry::shape_surface). Not the piece's own edges: those a cut leaves short
  // would shrink the caps of every cut after it.
  const double edge_length = bounds.diagonal().norm() / 40;
  // The split needs no more than a closed surface: it keeps what it is given, crossings
  // included (and no test of them, a third of the pencil's cut surface, is made), and no
  // CGAL mesh of it. A polygon over the whole section is split alike: corefinement left the
  // two sides of a box cut through by a square joined, neither closed.
  for (std::size_t b = 0; b < blades.size(); ++b)
    if (!blades[b]->surface && (blades[b]->polygon.empty() || covers_section(surface, triangles, *exact[b]))) {
      if (blades.size() > 1) throw NotAtOnce();
      return surface_cut::cut_piece_by_plane(std::move(arrays), *exact[b], edge_length, out);
    }
  // Corefinement takes the piece as a CGAL mesh, each vertex with "v:input" (−1 for the
  // vertices a cut adds), which CGAL carries through its operations. Its precondition: a
  // piece that intersects itself (or was found to, `marked_intersecting`) is left whole
  // rather than cut into garbage.
  Mesh piece;
  const auto input_of = piece.add_property_map<Mesh::Vertex_index, int>("v:input", -1).first;
  // A recycled slot would keep the removed vertex's "v:input": new vertices go at the end.
  piece.set_recycle_garbage(false);
  for (std::size_t v = 0; v < arrays.points.size(); ++v) input_of[piece.add_vertex(arrays.points[v])] = arrays.input[v];
  for (const std::array<int, 3>& corners : arrays.triangles)
    piece.add_face(Mesh::Vertex_index(static_cast<Mesh::size_type>(corners[0])),
                   Mesh::Vertex_index(static_cast<Mesh::size_type>(corners[1])),
                   Mesh::Vertex_index(static_cast<Mesh::size_type>(corners[2])));
  if (marked_intersecting || PMP::does_self_intersect(piece)) throw SelfIntersectingPiece();
  return surface_cut::cut_piece_by_blades(piece, blades, edge_length, out);
}

// `surface` cut by `blades` at once, each piece by those that cross it (a blade with
// piece_at only the piece nearest that point); with `spanning_only` each piece by the first
// that is a whole plane or spans its section alone. Throws NotAtOnce.
SurfaceCut cut_surface_by(const SurfaceMesh& surface, const std::vector<CuttingPlane>& blades,
                          bool spanning_only = false) {
  std::vector<ExactBlade> exact;
  // A surface blade (only ever cut on its own) decides no side itself: corefinement does.
  for (const CuttingPlane& blade : blades) exact.emplace_back(blade.surface ? CuttingPlane() : blade);
  const std::vector<int> piece_of = surface_vertex_pieces(surface);
  std::map<int, std::vector<int>> triangles_of;
  for (Eigen::Index t = 0; t < surface.triangles.rows(); ++t)
    triangles_of[piece_of[surface.triangles(t, 0)]].push_back(static_cast<int>(t));
  std::vector<std::optional<int>> only(blades.size());
  for (std::size_t b = 0; b < blades.size(); ++b)
    if (blades[b].piece_at) {
      Eigen::Index nearest = 0;
      (surface.vertices.rowwise() - blades[b].piece_at->transpose()).rowwise().squaredNorm().minCoeff(&nearest);
      only[b] = piece_of[nearest];
    }

  CutPieces cut;
  cut.input_count = surface.vertices.rows();
  const bool marks_apply = surface.self_intersecting.size() == static_cast<std::size_t>(surface.triangles.rows());
  std::vector<char> self_intersecting;  // per output triangle
  std::vector<int> pieces_intersecting_themselves;
  int left_whole = 0;
  std::vector<char> in_opened_piece(static_cast<std::size_t>(surface.vertices.rows()), 0);
  for (const auto& [piece, triangles] : triangles_of) {
    bool opened = false, grazed = false,
         intersects_itself = marks_apply && surface.self_intersecting[triangles.front()];
    std::vector<const CuttingPlane*> crossing;
    std::vector<const ExactBlade*> crossing_exact;
    for (std::size_t b = 0; b < blades.size(); ++b)
      if (blades[b].surface) {
        if (!spanning_only && meets_bounds(surface, triangles, *blades[b].surface)) {
          crossing.push_back(&blades[b]);
          crossing_exact.push_back(&exact[b]);
        }
      } else if ((!only[b] || *only[b] == piece) && separates(surface, triangles, exact[b]) &&
                 clearly_separates(surface, triangles, blades[b]) &&
                 (!spanning_only ||
                  (crossing.empty() && (blades[b].polygon.empty() || covers_section(surface, triangles, exact[b]))))) {
        crossing.push_back(&blades[b]);
        crossing_exact.push_back(&exact[b]);
      }
    if (!crossing.empty()) {
      // A piece an earlier cut made intersect itself is left whole by a polygon (counted)
      // rather than failing the run; it is found once, when the cut after the one that
      // made it so tries it, and remembered in the surface. A whole plane splits it all
      // the same, its sides keeping the mark.
      try {
        opened = cut_piece(surface, triangles, crossing, crossing_exact, intersects_itself, cut);
        grazed = !opened;
      } catch (const NotAtOnce&) {
        throw;
      } catch (const SelfIntersectingPiece&) {
        intersects_itself = true;
      } catch (const std::exception&) {
        // Another refusal (corefinement's, or a split whose sides do not close) is this
        // blade's: the next one tries again.
      }
      left_whole += !opened && !grazed;
    }
    if (!opened)
      for (const int t : triangles)
        cut.triangles.push_back({surface.triangles(t, 0), surface.triangles(t, 1), surface.triangles(t, 2)});
    else
      for (const int t : triangles)
        for (int k = 0; k < 3; ++k) in_opened_piece[surface.triangles(t, k)] = 1;
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
  // Those of earlier cuts in pieces this one left whole keep theirs: their triangles are
  // as they were, in the same order (and cut points lie inside the body's bounds).
  std::vector<char> on_cut(static_cast<std::size_t>(out.vertices.rows()), 0);
  for (const int vertex : cut.cut_vertices) on_cut[vertex] = 1;
  out.embedding_offsets = Eigen::MatrixXd::Zero(out.vertices.rows(), 3);
  if (surface.embedding_offsets.size() != 0)
    for (Eigen::Index v = 0; v < cut.input_count; ++v) {
      if (surface.embedding_offsets.row(v).isZero()) continue;
      if (in_opened_piece[v]) on_cut[v] = 1;
      else out.embedding_offsets.row(v) = surface.embedding_offsets.row(v);
    }
  const Eigen::MatrixXd normals = vertex_normals(out, on_cut);
  const double hair = 1e-7 * bounding_box(out.vertices).diagonal();
  for (Eigen::Index v = 0; v < out.vertices.rows(); ++v) {
    const double length = normals.row(v).norm();
    if (on_cut[v] && length > 1e-6) out.embedding_offsets.row(v) = -hair / length * normals.row(v);
  }
  return result;
}

// `before` cut again by `blades`: the whole planes one after the other, then the polygons
// that span a piece's section, a piece at a time, then the other polygons and the surface
// blades at once (the pieces the same, cuts being sets: what splits a piece as a plane does
// first, since a notch leaves a slit no plane's section can close, and no corefinement
// takes a piece whose caps lie on one another). Throws NotAtOnce.
SurfaceCut cut_again(const SurfaceMesh& before, const std::vector<CuttingPlane>& blades) {
  SurfaceCut result{before, {}};
  int cap_triangles = 0;
  std::vector<CuttingPlane> one_by_one, finite;  // the whole planes; the finite and surface blades
  for (const CuttingPlane& blade : blades)
    if (!blade.surface && blade.polygon.empty()) one_by_one.push_back(blade);
    else finite.push_back(blade);
  for (const CuttingPlane& blade : one_by_one) {
    result = cut_surface_by(result.surface, {blade});
    if (result.facts["pieces_left_whole"].get<int>() > 0) return result;
    cap_triangles += result.facts["cap_triangles"].get<int>();
  }
  for (std::size_t pass = 0; pass < finite.size(); ++pass) {
    SurfaceCut spanned = cut_surface_by(result.surface, finite, true);
    if (spanned.facts["pieces_left_whole"].get<int>() > 0) return spanned;
    if (spanned.facts["cap_triangles"].get<int>() == 0) break;
    cap_triangles += spanned.facts["cap_triangles"].get<int>();
    result = std::move(spanned);
  }
  if (!finite.empty()) {
    result = cut_surface_by(result.surface, finite);
    cap_triangles += result.facts["cap_triangles"].get<int>();
  }
  result.facts["added_triangles"] = result.surface.triangles.rows() - before.triangles.rows();
  result.facts["added_vertices"] = result.surface.vertices.rows() - before.vertices.rows();
  result.facts["cap_triangles"] = cap_triangles;
  return result;
}

}  // namespace

SurfaceCut cut_surface(const SurfaceMesh& surface, const CuttingPlane& blade) {
  SurfaceCut result = cut_surface_by(surface, {blade});
  // A blade that changes nothing (one that misses the body) keeps the record as it is.
  if (result.facts["cap_triangles"].get<int>() == 0 && result.facts["pieces_left_whole"].get<int>() == 0) return result;
  // A piece an earlier finite or surface blade notched has its caps on one another, where
  // corefinement cannot cut and no plane's section closes: the surface before that blade
  // is cut again, with the blades since and this one (a sweep's earlier blades left out:
  // this one covers them).
  if (const SurfaceCutRecord* record = surface.cut_record.get();
      record && result.facts["pieces_left_whole"].get<int>() > 0) {
    // An earlier polygon of this one's plane that it overlaps, their union convex, is cut
    // with it as that union (coplanar_blades.hpp): their caps would lie on one another.
    std::vector<CuttingPlane> blades;
    CuttingPlane last = blade;
    for (const CuttingPlane& earlier : record->blades) {
      if (!blade.sweep.empty() && earlier.sweep == blade.sweep) continue;
      if (std::optional<CuttingPlane> joined = convex_union_blade(earlier, last)) last = std::move(*joined);
      else blades.push_back(earlier);
    }
    blades.push_back(last);
    try {
      SurfaceCut again = cut_again(record->before, blades);
      if (again.facts["pieces_left_whole"].get<int>() == 0) {
        again.facts["blades_cut_again"] = blades.size() - 1;
        again.surface.cut_record = std::make_shared<SurfaceCutRecord>(SurfaceCutRecord{record->before, blades});
        return again;
      }
    } catch (const NotAtOnce&) {
      // Polygons over one piece, one of them over its whole section: it stays whole.
    }
  }
  // Where a finite or surface blade since the record's surface may have notched a piece,
  // the record goes on from that surface with this blade too: else a cut the notch did not
  // stop (a plane beside it) made the notched surface the record's, and a later blade that
  // met the notch found its caps on one another there again.
  const SurfaceCutRecord* earlier = surface.cut_record.get();
  const auto finite = [](const CuttingPlane& cut) { return cut.surface || !cut.polygon.empty(); };
  if (earlier && std::any_of(earlier->blades.begin(), earlier->blades.end(), finite)) {
    SurfaceCutRecord record = *earlier;
    record.blades.push_back(blade);
    result.surface.cut_record = std::make_shared<SurfaceCutRecord>(std::move(record));
    return result;
  }
  SurfaceMesh before = surface;
  before.cut_record.reset();
  result.surface.cut_record = std::make_shared<SurfaceCutRecord>(SurfaceCutRecord{std::move(before), {blade}});
  return result;
}

}  // namespace altfem
