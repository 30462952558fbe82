#include "shared/mesh/grid_slicer.hpp"

#include <algorithm>
#include <functional>
#include <string>

#include "shared/common/error.hpp"
#include "shared/geometry/points_inside_surface.hpp"
#include "shared/mesh/grid_face_region.hpp"
#include "shared/mesh/split_holes.hpp"

namespace altfem {

namespace {

// A grid face's in-plane coordinates (u, v) = (x_(axis+1), x_(axis+2)): counter-clockwise
// about +e_axis is counter-clockwise in (u, v).
std::function<Eigen::Vector2d(int)> grid_face_coordinates(const std::vector<Eigen::Vector3d>& points, int axis) {
  return
      [&points, axis](int node) { return Eigen::Vector2d(points[node]((axis + 1) % 3), points[node]((axis + 2) % 3)); };
}

}  // namespace

SlicedMesh GridSlicer::run() {
  grid_node_ids_.assign(static_cast<std::size_t>((grid_.cells.array() + 1).prod()), -1);
  const SurfacePieces pieces = split_surface_by_grid(surface_, grid_, nodes_);
  cell_pieces_.resize(grid_.cell_count());
  for (std::size_t p = 0; p < pieces.polygons.size(); ++p) cell_pieces_[pieces.cells[p]].push_back(static_cast<int>(p));
  classify_uncut_cells();
  collect_open_edges(pieces);
  compute_face_regions();
  return assemble(pieces);
}

void GridSlicer::classify_uncut_cells() {
  state_.assign(grid_.cell_count(), CellState::cut);
  std::vector<int> uncut;
  for (int cell = 0; cell < grid_.cell_count(); ++cell)
    if (!is_cut(cell)) uncut.push_back(cell);
  Eigen::MatrixXd centres(uncut.size(), 3);
  for (std::size_t i = 0; i < uncut.size(); ++i)
    centres.row(i) = grid_.grid_node(grid_.cell_coordinates(uncut[i])).array() + grid_.cell_size / 2;
  const auto sides = points_inside_surface(surface_.vertices, surface_.triangles, centres);
  for (std::size_t i = 0; i < uncut.size(); ++i)
    state_[uncut[i]] = sides[i] == SurfaceSide::inside ? CellState::inside : CellState::outside;
}

void GridSlicer::collect_open_edges(const SurfacePieces& pieces) {
  const auto& points = nodes_.points();
  for (int cell = 0; cell < grid_.cell_count(); ++cell) {
    if (!is_cut(cell)) continue;
    std::unordered_map<long long, int> balance;  // undirected edge → (# low→high) − (# high→low)
    for (int p : cell_pieces_[cell]) {
      const auto& loop = pieces.polygons[p];
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const int a = loop[i], b = loop[(i + 1) % loop.size()];
        balance[edge_key(a, b)] += a < b ? 1 : -1;
      }
    }
    auto& faces = face_segments_[cell];
    const Eigen::Vector3i coordinates = grid_.cell_coordinates(cell);
    for (const auto& [key, count] : balance) {
      if (count == 0) continue;
      int from = static_cast<int>(key >> 32), to = static_cast<int>(key & 0xffffffff);
      if (count < 0) std::swap(from, to);
      // The open edge from → to; its face holds the segment to → from.
      const Eigen::Vector3d& p = points[from];
      const Eigen::Vector3d& q = points[to];
      std::vector<int> candidates;
      for (int axis = 0; axis < 3; ++axis)
        for (int upper = 0; upper < 2; ++upper) {
          const double plane = grid_.planes[axis][coordinates(axis) + upper];
          if (p(axis) == plane && q(axis) == plane) candidates.push_back(2 * axis + upper);
        }
      if (candidates.empty() || std::abs(count) != 1)
        throw NumericalError("slicing: grid cell " + std::to_string(cell) +
                             ": the surface pieces do not close (open or non-manifold surface)");
      int chosen = candidates[0];
      if (candidates.size() == 2) {
        // On a cell edge: the face whose rectangle lies to the left of the segment.
        const Eigen::Vector3d direction = p - q;
        const Eigen::Vector3d normal = outward_normal(candidates[0]), other = outward_normal(candidates[1]);
        chosen = normal.cross(direction).dot(-other) > 0 ? candidates[0] : candidates[1];
      }
      faces[chosen].push_back({to, from});
    }
  }
}

long long GridSlicer::edge_key(int a, int b) {
  return (static_cast<long long>(std::min(a, b)) << 32) | static_cast<long long>(std::max(a, b));
}

Eigen::Vector3d GridSlicer::outward_normal(int local_face) {
  return (local_face % 2 ? 1.0 : -1.0) * Eigen::Vector3d::Unit(local_face / 2);
}

GridFaceRegion GridSlicer::region_from(const GridFace& face, int cell, bool cell_is_lower) {
  GridFaceView view{face.axis, corners_up(face), face_name(face)};
  if (!cell_is_lower) std::reverse(view.corners.begin(), view.corners.end());
  const auto found = face_segments_.find(cell);
  static const Segments none;
  const Segments& segments =
      found == face_segments_.end() ? none : found->second[2 * face.axis + (cell_is_lower ? 1 : 0)];
  GridFaceRegion region = grid_face_region(view, segments, nodes_.points());
  if (!cell_is_lower) {
    for (auto& loop : region.loops) std::reverse(loop.begin(), loop.end());
    for (auto& loop : region.holes) std::reverse(loop.begin(), loop.end());
  }
  return region;
}

GridSlicer::Loops GridSlicer::canonical(Loops loops) {
  for (auto& loop : loops) std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
  std::sort(loops.begin(), loops.end());
  return loops;
}

void GridSlicer::compute_face_regions() {
  std::vector<UndeterminedFace> undetermined_faces;
  for (int cell = 0; cell < grid_.cell_count(); ++cell) {
    if (!is_cut(cell)) continue;
    const Eigen::Vector3i coordinates = grid_.cell_coordinates(cell);
    for (int axis = 0; axis < 3; ++axis)
      for (int upper = 0; upper < 2; ++upper) {
        GridFace face{axis, coordinates};
        face.node(axis) += upper;
        const long long key = face_key(face);
        if (regions_.count(key)) continue;
        const int lower = lower_cell(face), above = upper_cell(face);
        const bool lower_cut = lower >= 0 && is_cut(lower), upper_cut = above >= 0 && is_cut(above);
        GridFaceRegion region = region_from(face, lower_cut ? lower : above, lower_cut);
        if (lower_cut && upper_cut) {
          const GridFaceRegion other = region_from(face, above, false);
          if (other.undetermined != region.undetermined || canonical(other.loops) != canonical(region.loops) ||
              canonical(other.holes) != canonical(region.holes))
            throw SurfaceInGridPlane("slicing: " + face_name(face) +
                                     ": the surface lies in this grid plane with material on both sides; "
                                     "change the resolution or the margin");
        }
        const bool undetermined = region.undetermined;
        Loops loops =
            region.holes.empty()
                ? std::move(region.loops)
                : split_holes(std::move(region.loops), region.holes, grid_face_coordinates(nodes_.points(), axis),
                              "slicing: " + face_name(face) +
                                  ": the surface pierces the face in several holes that cannot be "
                                  "bridged; change the resolution or the margin");
        if (undetermined) undetermined_faces.push_back({face, lower_cut && upper_cut, lower_cut ? -1.0 : 1.0});
        else check_next_to_inside_cell(face, loops, lower_cut ? above : lower, lower_cut && upper_cut);
        regions_.emplace(key, std::move(loops));
      }
  }
  decide_undetermined_faces(undetermined_faces);
}

void GridSlicer::decide_undetermined_faces(const std::vector<UndeterminedFace>& faces) {
  auto centre_of = [&](const GridFace& face) {
    Eigen::Vector3d centre = grid_.grid_node(face.node).array() + grid_.cell_size / 2;
    centre(face.axis) = grid_.planes[face.axis][face.node(face.axis)];
    return centre;
  };
  Eigen::MatrixXd centres(faces.size(), 3);
  for (std::size_t f = 0; f < faces.size(); ++f) centres.row(f) = centre_of(faces[f].face);
  const auto sides = points_inside_surface(surface_.vertices, surface_.triangles, centres);
  std::vector<std::size_t> in_plane;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (sides[f] != SurfaceSide::on_surface) continue;
    if (faces[f].both_cut)
      throw SurfaceInGridPlane(
          "slicing: " + face_name(faces[f].face) +
          ": the surface lies in this grid plane between two cut cells; change the resolution or the margin");
    in_plane.push_back(f);
  }
  Eigen::MatrixXd probes(in_plane.size(), 3);
  for (std::size_t p = 0; p < in_plane.size(); ++p) {
    const UndeterminedFace& undetermined = faces[in_plane[p]];
    Eigen::Vector3d probe = centres.row(in_plane[p]);
    probe(undetermined.face.axis) += undetermined.towards_cut_cell * 1e-6 * grid_.cell_size;
    probes.row(p) = probe;
  }
  const auto probe_sides = points_inside_surface(surface_.vertices, surface_.triangles, probes);
  std::vector<SurfaceSide> decided = sides;
  for (std::size_t p = 0; p < in_plane.size(); ++p) decided[in_plane[p]] = probe_sides[p];
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const GridFace& face = faces[f].face;
    Loops& loops = regions_[face_key(face)];
    if (decided[f] == SurfaceSide::inside) {
      const auto corners = corners_up(face);
      loops.push_back({corners.begin(), corners.end()});
    }
    const int other = faces[f].towards_cut_cell < 0 ? upper_cell(face) : lower_cell(face);
    check_next_to_inside_cell(face, loops, other, faces[f].both_cut);
  }
}

void GridSlicer::check_next_to_inside_cell(const GridFace& face, const Loops& loops, int other_cell, bool both_cut) {
  if (both_cut || other_cell < 0 || state_[other_cell] != CellState::inside) return;
  const auto corners = corners_up(face);
  if (canonical(loops) != canonical({{corners.begin(), corners.end()}}))
    throw SurfaceInGridPlane("slicing: " + face_name(face) +
                             ": the surface lies in this grid plane next to a cell wholly inside; "
                             "change the resolution or the margin");
}

}  // namespace altfem
