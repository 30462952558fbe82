#include "shared/mesh/cut_by_surface.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <set>
#include <stdexcept>
#include <string>

#include "shared/common/error.hpp"
#include "shared/geometry/exact_orientation.hpp"
#include "shared/geometry/polyhedron_moments.hpp"
#include "shared/mesh/bounding_box.hpp"
#include "shared/mesh/cut_polyhedral_pieces.hpp"
#include "shared/mesh/disjoint_sets.hpp"
#include "shared/mesh/merge_slivers.hpp"
#include "shared/mesh/polyhedral_mesh_window.hpp"
#include "shared/mesh/simplify_cut_faces.hpp"
#include "shared/mesh/surface_cut_debris.hpp"

namespace altfem {

namespace {

// A node within this fraction of the mesh's diagonal of a blade step's plane is on it (a
// new node as near a corner of its triangle is that corner). The planes of the triangles
// around a blade's vertex, and of their edges, all pass through it and through the lines
// of its edges, and cross a cell's edge near one of those lines within 1e-13 to 1e-10 of
// one another as rounded (the finer the blade, the flatter its dihedral angles and the
// farther apart): at the default snapping distance each crossing was a node of its own,
// and harmonic's bases, fitted through nodes a rounding apart, gave a singular stiffness.
constexpr double blade_snap_fraction = 1e-9;

// Per triangle and edge k (from corner k to k + 1), whether the blade goes on across it
// in the triangle's plane: the edge is another triangle's too, whose third corner lies in
// this one's plane (an exact predicate). Then both sides of the edge separate, and
// splitting the cells by the plane through it would only add pieces. And per triangle its
// flat part of the blade: the triangles joined across such edges, all in one plane.
struct BladeEdges {
  std::vector<std::array<bool, 3>> within;
  std::vector<int> flat_part;  ///< per triangle, the smallest triangle of its flat part
};

BladeEdges edges_within_a_plane(const SurfaceBlade& blade) {
  const auto triangles = static_cast<int>(blade.triangles.rows());
  std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> holders;  // edge → (triangle, its corner k)
  for (int triangle = 0; triangle < triangles; ++triangle)
    for (int k = 0; k < 3; ++k)
      holders[std::minmax(blade.triangles(triangle, k), blade.triangles(triangle, (k + 1) % 3))].push_back(
          {triangle, k});
  const auto corner = [&](int triangle, int k) -> Eigen::Vector3d {
    return blade.vertices.row(blade.triangles(triangle, k % 3)).transpose();
  };
  BladeEdges edges{std::vector<std::array<bool, 3>>(static_cast<std::size_t>(triangles), {false, false, false}), {}};
  DisjointSets flat(triangles);
  for (const auto& [edge, sharing] : holders) {
    if (sharing.size() != 2) continue;
    const auto [first, k] = sharing[0];
    const auto [second, j] = sharing[1];
    if (orientation_sign(corner(first, 0), corner(first, 1), corner(first, 2), corner(second, j + 2)) != 0) continue;
    edges.within[first][k] = edges.within[second][j] = true;
    flat.join(flat.find(first), flat.find(second));
  }
  std::vector<int> smallest(static_cast<std::size_t>(triangles), triangles);
  for (int triangle = 0; triangle < triangles; ++triangle)
    smallest[flat.find(triangle)] = std::min(smallest[flat.find(triangle)], triangle);
  for (int triangle = 0; triangle < triangles; ++triangle) edges.flat_part.push_back(smallest[flat.find(triangle)]);
  return edges;
}

}  // namespace

std::vector<SurfaceBladeStep> surface_blade_steps(const SurfaceBlade& blade) {
  std::vector<SurfaceBladeStep> steps;
  const BladeEdges edges = edges_within_a_plane(blade);
  std::vector<CuttingPlane> planes;
  for (Eigen::Index triangle = 0; triangle < blade.triangles.rows(); ++triangle) {
    std::vector<Eigen::Vector3d> corners;
    for (int k = 0; k < 3; ++k) corners.push_back(blade.vertices.row(blade.triangles(triangle, k)).transpose());
    planes.push_back(polygon_blade(corners));
    if (const std::string problem = blade_polygon_problem(planes.back()); !problem.empty())
      throw std::invalid_argument("cut: triangle " + std::to_string(triangle) + " of the blade surface: " + problem);
  }
  for (Eigen::Index triangle = 0; triangle < blade.triangles.rows(); ++triangle) {
    const int index = static_cast<int>(triangle);
    const int flat_part = edges.flat_part[triangle];
    CuttingPlane plane = planes[triangle];
    // A flat part's triangles on its first one's plane, point and normal (each its own
    // sense): their side planes along the edges they share are then the same (ExactBlade).
    const CuttingPlane& part_plane = planes[flat_part];
    plane.point = part_plane.point;
    plane.normal = plane.normal.dot(part_plane.normal) < 0 ? Eigen::Vector3d(-part_plane.normal) : part_plane.normal;
    const std::vector<Eigen::Vector3d>& corners = plane.polygon;
    Eigen::AlignedBox3d box;
    for (const Eigen::Vector3d& corner : corners) box.extend(corner);
    const std::array<Eigen::Vector3d, 3> triangle_corners{corners[0], corners[1], corners[2]};
    steps.push_back(
        {CuttingPlane(plane.point, plane.normal), {CutAction::split, box}, true, triangle_corners, index, flat_part});
    for (int k = 0; k < 3; ++k) {
      if (edges.within[triangle][k]) continue;
      const Eigen::Vector3d& from = corners[k];
      const Eigen::Vector3d& to = corners[(k + 1) % 3];
      Eigen::AlignedBox3d edge_box(from.cwiseMin(to), from.cwiseMax(to));
      steps.push_back({CuttingPlane(from, (to - from).cross(plane.normal)),
                       {CutAction::split, edge_box},
                       false,
                       triangle_corners,
                       index,
                       flat_part});
    }
    steps.push_back({plane, {CutAction::separate, box}, true, triangle_corners, index, flat_part});
  }
  // A flat part's triangles one after another: their pieces are joined once all of them
  // are cut (cut_window_by_flat_part).
  std::stable_sort(steps.begin(), steps.end(),
                   [](const SurfaceBladeStep& a, const SurfaceBladeStep& b) { return a.flat_part < b.flat_part; });
  return steps;
}

CutScope TrianglePlaneNodes::scope_for(const SurfaceBladeStep& step) {
  CutScope scope = step.scope;
  scope.snap_fraction = blade_snap_fraction;
  scope.on_plane = step.triangle_plane ? &on_plane_ : &none_;
  return scope;
}

void TrianglePlaneNodes::after(const SurfaceBladeStep& step, const Eigen::MatrixXd& nodes,
                               const std::vector<NodeSource>& sources, Eigen::Index nodes_before) {
  if (step.scope.action == CutAction::separate) return;
  is_on_plane_.resize(static_cast<std::size_t>(nodes.rows()), false);
  if (step.triangle_plane) {
    // The split's crossing nodes; and the nodes exactly on the plane, which its edges'
    // splits may join.
    const ExactBlade plane(step.plane);
    for (Eigen::Index node = 0; node < nodes.rows(); ++node)
      if (node >= nodes_before || plane.side(nodes.row(node).transpose()) == 0) is_on_plane_[node] = true;
  } else {
    for (Eigen::Index node = nodes_before; node < nodes.rows(); ++node) {
      const NodeSource& source = sources[node];
      is_on_plane_[node] = is_on_plane_[source.first] && is_on_plane_[source.second];
    }
  }
  on_plane_.clear();
  for (std::size_t node = 0; node < is_on_plane_.size(); ++node)
    if (is_on_plane_[node]) on_plane_.push_back(static_cast<int>(node));
}

namespace {

// `origin` (per node) of the nodes `kept` (per node after, its index before).
void keep_origins(std::vector<int>& origin, const std::vector<int>& kept) {
  std::vector<int> kept_origin(kept.size());
  for (std::size_t node = 0; node < kept.size(); ++node) kept_origin[node] = origin[kept[node]];
  origin = std::move(kept_origin);
}

// The window's pieces once joined (join_pieces_by_side) keep every face piece and node the
// steps put on their faces, which the next flat part's steps would cut again: the faces in
// one plane between the same two cells merged and the steps' nodes in the middle of
// straight edges dropped (simplify_cut_faces.hpp, `straight` its tolerance), as after the
// whole cut, but no shell face nor a node of the window's (the cells outside hold them).
// `origin` (per node) follows the nodes kept.
void simplify_joined_window(PolyhedralMesh& cut, const PolyhedralMeshWindow& window, double straight,
                            std::vector<int>& origin) {
  std::set<std::vector<int>> shell;
  for (const int face : window.shell_window_faces) shell.insert(window.mesh.faces[face]);
  std::vector<bool> fixed(static_cast<std::size_t>(cut.face_count()));
  for (int face = 0; face < cut.face_count(); ++face)
    fixed[face] = cut.face_cells(face, 1) < 0 && shell.count(cut.faces[face]) > 0;
  PolyhedralMesh simplified = cut;
  merge_coplanar_faces(simplified, straight, &fixed);
  const auto window_nodes = static_cast<int>(window.nodes.size());
  drop_straight_run_nodes(simplified, straight, window_nodes);
  const std::vector<int> kept = drop_unused_nodes(simplified);
  // A node of the window's inside the faces it merged (one an earlier flat part left) would
  // go, and with it the window's numbering that putting it back needs: then the window
  // stays as it was. `kept` ascends, so the window's nodes all stay where its first ones do.
  if (static_cast<int>(kept.size()) < window_nodes || kept[window_nodes - 1] != window_nodes - 1) return;
  cut = std::move(simplified);
  keep_origins(origin, kept);
}

// The steps of one flat part of the blade (`steps`: its triangles', one after another) on
// the window of `result`'s mesh about them, put back. `cell_boxes` per cell of that mesh; `bounds` the input mesh's
// bounding box, whose diagonal every step's snapping is a fraction of. `origin`: per node of `result`'s mesh, the input
// node it is or is a copy of (−1: made by a step); extended by the new nodes.
void cut_window_by_flat_part(PolyhedralCut& result, std::vector<Eigen::AlignedBox3d>& cell_boxes,
                             std::vector<int>& origin, const SurfaceBladeStep* steps, std::size_t count,
                             const Eigen::AlignedBox3d& bounds) {
  Eigen::AlignedBox3d reach;
  for (std::size_t k = 0; k < count; ++k)
    // A step away from the body (its region or, to separate, its triangle's box) changes nothing.
    if (steps[k].scope.region->intersects(bounds)) reach.extend(*steps[k].scope.region);
  if (reach.isEmpty()) return;
  const PolyhedralMeshWindow window = polyhedral_mesh_window(result.mesh, cell_boxes, reach);
  if (window.cells.empty()) return;
  PolyhedralMesh cut = window.mesh;
  std::vector<int> parents(window.cells.size());
  for (std::size_t cell = 0; cell < parents.size(); ++cell) parents[cell] = static_cast<int>(cell);
  const double diagonal = bounds.diagonal().norm();
  std::vector<int> window_origin(window.nodes.size());
  for (std::size_t node = 0; node < window.nodes.size(); ++node) window_origin[node] = origin[window.nodes[node]];
  TrianglePlaneNodes on_plane;
  for (std::size_t k = 0; k < count; ++k) {
    const SurfaceBladeStep& blade_step = steps[k];
    if (k > 0 && blade_step.triangle != steps[k - 1].triangle) on_plane = {};
    if (!blade_step.scope.region->intersects(bounds)) continue;
    const Eigen::Index nodes_before = cut.nodes.rows();
    CutScope scope = on_plane.scope_for(blade_step);
    scope.snap_length = diagonal;
    PolyhedralCut step = cut_snapping_less_if_need_be(
        [&](const CutScope& tried) { return cut_polyhedral_mesh(cut, blade_step.plane, false, tried); }, scope);
    on_plane.after(blade_step, step.mesh.nodes, step.node_sources, nodes_before);
    for (Eigen::Index node = nodes_before; node < step.mesh.nodes.rows(); ++node) {
      const NodeSource& source = step.node_sources[node];
      window_origin.push_back(source.weight == 0 ? window_origin[source.first] : -1);  // a copy, or a crossing
    }
    fold_step_counts(result, step, parents, step.parent_cell);
    cut = std::move(step.mesh);
    snap_new_nodes_to_corners(cut, nodes_before, blade_step.corners, blade_snap_fraction * diagonal);
    weld_coincident_neighbours(cut);
  }
  // The pieces each side of the flat part, joined again: without, every plane of a finely
  // curved blade multiplied the pieces near it (fcm's and fem's fragments, which stay
  // convex, by about five a triangle). Not before its last triangle: a triangle's
  // separation opens the faces in its plane that it covers, split along its edges but not
  // along those it shares with the flat part's other triangles, which their own edges'
  // splits bound.
  const auto own_split = std::find_if(steps, steps + count, [](const SurfaceBladeStep& step) {
    return step.triangle_plane && step.scope.action == CutAction::split;
  });
  std::vector<int> kept_nodes;
  if (own_split != steps + count && join_pieces_by_side(cut, parents, own_split->plane, &kept_nodes) > 0) {
    keep_origins(window_origin, kept_nodes);
    simplify_joined_window(cut, window, 1e-12 * diagonal, window_origin);
  }
  origin.insert(origin.end(), window_origin.begin() + static_cast<std::ptrdiff_t>(window.nodes.size()),
                window_origin.end());
  splice_polyhedral_mesh_window(result.mesh, cell_boxes, result.parent_cell, window, std::move(cut), parents);
}

}  // namespace

PolyhedralCut cut_by_surface_steps(const PolyhedralMesh& mesh, const SurfaceBlade& blade, std::vector<int>* origin) {
  PolyhedralCut result;
  result.mesh = mesh;
  result.parent_cell.resize(static_cast<std::size_t>(mesh.cell_count()));
  for (int cell = 0; cell < mesh.cell_count(); ++cell) result.parent_cell[cell] = cell;
  Eigen::AlignedBox3d bounds;
  for (Eigen::Index node = 0; node < mesh.nodes.rows(); ++node) bounds.extend(mesh.nodes.row(node).transpose());
  std::vector<Eigen::AlignedBox3d> cell_boxes = polyhedral_cell_boxes(result.mesh);
  std::vector<int> origins(static_cast<std::size_t>(mesh.nodes.rows()));
  std::iota(origins.begin(), origins.end(), 0);
  const std::vector<SurfaceBladeStep> steps = surface_blade_steps(blade);
  for (std::size_t first = 0, last = 0; first < steps.size(); first = last) {
    while (last < steps.size() && steps[last].flat_part == steps[first].flat_part) ++last;
    cut_window_by_flat_part(result, cell_boxes, origins, &steps[first], last - first, bounds);
  }
  if (origin) *origin = std::move(origins);
  return result;
}

PolyhedralCut cut_polyhedral_mesh_by_surface(const PolyhedralMesh& mesh, const SurfaceBlade& blade,
                                             bool compute_geometry) {
  PolyhedralCut result = cut_by_surface_steps(mesh, blade);
  const FacesSeparated rounding = separate_faces_of_rounding_area(result.mesh, blade);
  result.separated_faces += rounding.faces;
  result.duplicated_nodes += rounding.duplicated_nodes;
  join_unparted_pieces(result.mesh, result.parent_cell);
  weld_coincident_neighbours(result.mesh);
  result.dropped_pieces = drop_isolated_slivers(result.mesh, result.parent_cell, mesh);
  const double straight = 1e-12 * bounding_box(mesh.nodes).diagonal();
  result.merged_faces = merge_coplanar_faces(result.mesh, straight);
  result.dropped_nodes = drop_straight_run_nodes(result.mesh, straight);
  drop_unused_nodes(result.mesh);
  std::vector<int> pieces_of(static_cast<std::size_t>(mesh.cell_count()), 0);
  for (const int parent : result.parent_cell) ++pieces_of[parent];
  for (const int pieces : pieces_of) result.crossed_cells += pieces > 1 ? 1 : 0;
  if (!compute_geometry) return result;
  try {
    compute_polyhedral_geometry(result.mesh);
  } catch (const NumericalError&) {
    // As a planar cut: pieces a few 1e-12 thin, merged into a neighbour.
    std::vector<bool> is_piece(result.parent_cell.size());
    for (std::size_t piece = 0; piece < is_piece.size(); ++piece)
      is_piece[piece] = pieces_of[result.parent_cell[piece]] > 1;
    std::vector<NodeSource> sources(static_cast<std::size_t>(result.mesh.nodes.rows()));
    try {
      result.merged_pieces = merge_pieces_without_volume(result.mesh, result.parent_cell, sources, is_piece);
    } catch (const std::invalid_argument&) {  // a piece whose nodes coincide (below)
      throw NumericalError(
          "cut: the surface blade left pieces of no size, where its triangles' planes cut the "
          "cells into pieces of rounding size (a blade with fewer triangles meeting there cuts)");
    }
    if (result.merged_pieces == 0) throw;
    compute_polyhedral_geometry(result.mesh);
  }
  // Where many of the blade's triangles meet at a vertex, their planes cut the cells there
  // into pieces a few ulps across, whose rounded nodes can coincide: a face of no area, or
  // with an edge of none, is refused here rather than handed to a method.
  const auto has_no_size = [&](int face) {
    const std::vector<int>& loop = result.mesh.faces[face];
    for (std::size_t k = 0; k < loop.size(); ++k)
      if (result.mesh.nodes.row(loop[k]) == result.mesh.nodes.row(loop[(k + 1) % loop.size()])) return true;
    return !(result.mesh.face_areas(face) > 0);
  };
  for (int face = 0; face < result.mesh.face_count(); ++face)
    if (has_no_size(face)) {
      const Eigen::Vector3d at = result.mesh.face_centroids.row(face);
      throw NumericalError("cut: the surface blade left a face of no size at (" + std::to_string(at.x()) + ", " +
                           std::to_string(at.y()) + ", " + std::to_string(at.z()) +
                           "), where its triangles' planes cut the cells into pieces of rounding size (a blade "
                           "with fewer triangles meeting there cuts)");
    }
  return result;
}

}  // namespace altfem
