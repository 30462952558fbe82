#include "shared/mesh/slice_into_polyhedra.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>

#include "shared/common/error.hpp"
#include "shared/geometry/points_inside_surface.hpp"
#include "shared/mesh/boundary_surface.hpp"
#include "shared/mesh/disjoint_sets.hpp"
#include "shared/mesh/grid_face_region.hpp"
#include "shared/mesh/merge_slivers.hpp"
#include "shared/mesh/octree_grading.hpp"
#include "shared/mesh/slicing_grid.hpp"
#include "shared/mesh/tetrahedralize.hpp"

namespace altfem {

namespace {

using Loops = std::vector<std::vector<int>>;
using Segments = std::vector<std::array<int, 2>>;
constexpr const char* axis_names = "xyz";

/// A grid face: the plane x_axis = planes[axis][node(axis)], from grid node `node` over
/// one cell along the two other axes. Its lower cell is node − e_axis, its upper cell node.
struct GridFace {
  int axis;
  Eigen::Vector3i node;
};

class Slicer {
public:
  Slicer(const SurfaceMesh& surface, const SlicingGrid& grid) : surface_(surface), grid_(grid) {}

  SlicedMesh run() {
    const SurfacePieces pieces = split_surface_by_grid(surface_, grid_, nodes_);
    cell_pieces_.resize(grid_.cell_count());
    for (std::size_t p = 0; p < pieces.polygons.size(); ++p) cell_pieces_[pieces.cells[p]].push_back(static_cast<int>(p));
    classify_uncut_cells();
    collect_open_edges(pieces);
    compute_face_regions();
    return assemble(pieces);
  }
  /// After run(): per grid cell, the mesh cell of the hexahedron filling it, or −1.
  const std::vector<int>& grid_hexahedra() const { return grid_hexahedra_; }

private:
  enum class CellState : signed char { outside, inside, cut };

  bool is_cut(int cell) const { return !cell_pieces_[cell].empty(); }
  bool has_material(int cell) const { return cell >= 0 && state_[cell] != CellState::outside; }
  int cell_at(Eigen::Vector3i cell) const {
    for (int axis = 0; axis < 3; ++axis)
      if (cell(axis) < 0 || cell(axis) >= grid_.cells(axis)) return -1;
    return grid_.cell_index(cell);
  }
  long long face_key(const GridFace& face) const {
    const Eigen::Vector3i nodes = grid_.cells.array() + 1;
    return face.axis + 3LL * (face.node(0) + nodes(0) * (face.node(1) + static_cast<long long>(nodes(1)) * face.node(2)));
  }
  int lower_cell(const GridFace& face) const {
    Eigen::Vector3i cell = face.node;
    --cell(face.axis);
    return cell_at(cell);
  }
  int upper_cell(const GridFace& face) const { return cell_at(face.node); }
  std::string face_name(const GridFace& face) const {
    return std::string("grid face ") + axis_names[face.axis] + " = " + std::to_string(grid_.planes[face.axis][face.node(face.axis)]) +
           " at grid node (" + std::to_string(face.node(0)) + ", " + std::to_string(face.node(1)) + ", " +
           std::to_string(face.node(2)) + ")";
  }
  int grid_node(const Eigen::Vector3i& node) { return nodes_.node(grid_.grid_node(node)); }

  /// The corners counter-clockwise seen along +e_axis (outward for the lower cell).
  std::array<int, 4> corners_up(const GridFace& face) {
    const int b = (face.axis + 1) % 3, c = (face.axis + 2) % 3;
    const Eigen::Vector3i eb = Eigen::Vector3i::Unit(b), ec = Eigen::Vector3i::Unit(c);
    return {grid_node(face.node), grid_node(face.node + eb), grid_node(face.node + eb + ec), grid_node(face.node + ec)};
  }

  /// Uncut cells are wholly inside or outside: their centres decide (a centre is never on
  /// the surface, which does not enter an uncut cell).
  void classify_uncut_cells() {
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

  /// Per cut cell and local face (2·axis + upper), the open edges of its surface pieces
  /// that lie on that face, reversed: the segments grid_face_region chains.
  void collect_open_edges(const SurfacePieces& pieces) {
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
          throw NumericalError("slicing: grid cell " + std::to_string(cell) + ": the surface pieces do not close (open or non-manifold surface)");
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
  static long long edge_key(int a, int b) {
    return (static_cast<long long>(std::min(a, b)) << 32) | static_cast<long long>(std::max(a, b));
  }
  static Eigen::Vector3d outward_normal(int local_face) {
    return (local_face % 2 ? 1.0 : -1.0) * Eigen::Vector3d::Unit(local_face / 2);
  }

  /// The region of one grid face from one of its cut cells, as loops oriented along +e_axis.
  Loops region_from(const GridFace& face, int cell, bool cell_is_lower, bool& undetermined) {
    GridFaceView view{face.axis, corners_up(face), face_name(face)};
    if (!cell_is_lower) std::reverse(view.corners.begin(), view.corners.end());
    const auto found = face_segments_.find(cell);
    static const Segments none;
    const Segments& segments =
        found == face_segments_.end() ? none : found->second[2 * face.axis + (cell_is_lower ? 1 : 0)];
    GridFaceRegion region = grid_face_region(view, segments, nodes_.points());
    undetermined = region.undetermined;
    if (!cell_is_lower)
      for (auto& loop : region.loops) std::reverse(loop.begin(), loop.end());
    return std::move(region.loops);
  }

  static Loops canonical(Loops loops) {
    for (auto& loop : loops) std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
    std::sort(loops.begin(), loops.end());
    return loops;
  }

  /// Every grid face of a cut cell gets its loops (oriented along +e_axis) once.
  void compute_face_regions() {
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
          bool undetermined = false;
          Loops loops = region_from(face, lower_cut ? lower : above, lower_cut, undetermined);
          if (lower_cut && upper_cut) {
            bool other_undetermined = false;
            const Loops other = region_from(face, above, false, other_undetermined);
            if (other_undetermined != undetermined || canonical(other) != canonical(loops))
              throw NumericalError("slicing: " + face_name(face) +
                                   ": the surface lies in this grid plane with material on both sides; "
                                   "change the resolution or the margin");
          }
          if (undetermined)
            undetermined_faces.push_back({face, lower_cut && upper_cut, lower_cut ? -1.0 : 1.0});
          else
            check_next_to_inside_cell(face, loops, lower_cut ? above : lower, lower_cut && upper_cut);
          regions_.emplace(key, std::move(loops));
        }
    }
    decide_undetermined_faces(undetermined_faces);
  }

  /// A grid face of a cut cell that the surface does not cross.
  struct UndeterminedFace {
    GridFace face;
    bool both_cut;
    double towards_cut_cell;  ///< −1 or +1 along e_axis
  };

  /// Wholly inside or outside: the face centre decides, or, when the surface lies in the
  /// face's plane there (the centre is on it), a point just inside the cut cell.
  void decide_undetermined_faces(const std::vector<UndeterminedFace>& faces) {
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
        throw NumericalError("slicing: " + face_name(faces[f].face) +
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

  /// Next to a cell wholly inside, the cut cell's face region must be the whole face.
  void check_next_to_inside_cell(const GridFace& face, const Loops& loops, int other_cell, bool both_cut) {
    if (both_cut || other_cell < 0 || state_[other_cell] != CellState::inside) return;
    const auto corners = corners_up(face);
    if (canonical(loops) != canonical({{corners.begin(), corners.end()}}))
      throw NumericalError("slicing: " + face_name(face) +
                           ": the surface lies in this grid plane next to a cell wholly inside; "
                           "change the resolution or the margin");
  }

  SlicedMesh assemble(const SurfacePieces& pieces);

  const SurfaceMesh& surface_;
  const SlicingGrid& grid_;
  NodeRegistry nodes_;
  std::vector<std::vector<int>> cell_pieces_;  ///< per grid cell, its surface pieces
  std::vector<CellState> state_;
  std::unordered_map<int, std::array<Segments, 6>> face_segments_;
  std::unordered_map<long long, Loops> regions_;  ///< grid faces of cut cells → loops along +e_axis
  std::vector<int> grid_hexahedra_;
};

SlicedMesh Slicer::assemble(const SurfacePieces& pieces) {
  SlicedMesh result;
  PolyhedralMesh& mesh = result.mesh;
  std::vector<int> first_mesh_cell(grid_.cell_count(), -1);  // hexahedron, or the first piece of a cut cell
  grid_hexahedra_.assign(grid_.cell_count(), -1);
  std::vector<int> piece_cell(pieces.polygons.size(), -1);
  // (face key, lower side?) → the mesh cell of each loop on that side
  std::unordered_map<long long, std::vector<int>> loop_cells_lower, loop_cells_upper;
  int cell_count = 0;
  for (int cell = 0; cell < grid_.cell_count(); ++cell) {
    if (state_[cell] == CellState::outside) continue;
    first_mesh_cell[cell] = cell_count;
    if (state_[cell] == CellState::inside) {
      grid_hexahedra_[cell] = cell_count;
      mesh.cell_kinds.push_back(PolyhedralCellKind::hexahedron);
      ++cell_count;
      ++result.hexahedra;
      continue;
    }
    // The cut cell's closed boundary: its pieces and its faces' loops; pieces are the
    // connected components by shared edges (a vertex alone does not join them).
    std::vector<const std::vector<int>*> boundary;
    for (int p : cell_pieces_[cell]) boundary.push_back(&pieces.polygons[p]);
    const Eigen::Vector3i coordinates = grid_.cell_coordinates(cell);
    std::array<long long, 6> keys;
    for (int local = 0; local < 6; ++local) {
      GridFace face{local / 2, coordinates};
      face.node(face.axis) += local % 2;
      keys[local] = face_key(face);
      for (const auto& loop : regions_.at(keys[local])) boundary.push_back(&loop);
    }
    DisjointSets components(static_cast<int>(boundary.size()));
    std::unordered_map<long long, int> edge_owner;
    for (int f = 0; f < static_cast<int>(boundary.size()); ++f) {
      const auto& loop = *boundary[f];
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const auto [it, inserted] = edge_owner.emplace(edge_key(loop[i], loop[(i + 1) % loop.size()]), f);
        if (!inserted) components.join(it->second, f);
      }
    }
    std::unordered_map<int, int> component_cell;
    auto mesh_cell_of = [&](int f) {
      const auto [it, inserted] = component_cell.emplace(components.find(f), cell_count);
      if (inserted) {
        mesh.cell_kinds.push_back(PolyhedralCellKind::cut);
        ++cell_count;
      }
      return it->second;
    };
    int f = 0;
    for (int p : cell_pieces_[cell]) piece_cell[p] = mesh_cell_of(f++);
    for (int local = 0; local < 6; ++local) {
      auto& cells = (local % 2 ? loop_cells_lower : loop_cells_upper)[keys[local]];
      for (std::size_t loop = 0; loop < regions_.at(keys[local]).size(); ++loop) cells.push_back(mesh_cell_of(f++));
    }
    result.cut_pieces += static_cast<int>(component_cell.size());
    result.split_grid_cells += component_cell.size() > 1;
  }

  // Faces: the surface pieces (boundary), then every grid face with material on a side.
  std::vector<std::array<int, 2>> face_cells;
  auto add_face = [&](std::vector<int> loop, int lower, int upper) {
    if (lower < 0) {
      std::reverse(loop.begin(), loop.end());
      std::swap(lower, upper);
    }
    mesh.faces.push_back(std::move(loop));
    face_cells.push_back({lower, upper});
  };
  for (std::size_t p = 0; p < pieces.polygons.size(); ++p) add_face(pieces.polygons[p], piece_cell[p], -1);
  for (int axis = 0; axis < 3; ++axis) {
    Eigen::Vector3i extent = grid_.cells;
    ++extent(axis);
    for (int k = 0; k < extent(2); ++k)
      for (int j = 0; j < extent(1); ++j)
        for (int i = 0; i < extent(0); ++i) {
          const GridFace face{axis, Eigen::Vector3i(i, j, k)};
          const int lower = lower_cell(face), upper = upper_cell(face);
          if (!has_material(lower) && !has_material(upper)) continue;
          const auto region = regions_.find(face_key(face));
          if (region == regions_.end()) {  // between uncut cells: the whole rectangle
            const auto corners = corners_up(face);
            add_face({corners.begin(), corners.end()}, has_material(lower) ? first_mesh_cell[lower] : -1,
                     has_material(upper) ? first_mesh_cell[upper] : -1);
            continue;
          }
          const auto side_cells = [&](int cell, const auto& loop_cells, std::size_t loop) {
            if (!has_material(cell)) return -1;
            return state_[cell] == CellState::inside ? first_mesh_cell[cell] : loop_cells.at(region->first)[loop];
          };
          for (std::size_t loop = 0; loop < region->second.size(); ++loop)
            add_face(region->second[loop], side_cells(lower, loop_cells_lower, loop),
                     side_cells(upper, loop_cells_upper, loop));
        }
  }

  mesh.cell_faces.assign(cell_count, {});
  mesh.face_cells.resize(static_cast<Eigen::Index>(face_cells.size()), 2);
  for (std::size_t f = 0; f < face_cells.size(); ++f) {
    mesh.face_cells(f, 0) = face_cells[f][0];
    mesh.face_cells(f, 1) = face_cells[f][1];
    for (int side : face_cells[f])
      if (side >= 0) mesh.cell_faces[side].push_back(static_cast<int>(f));
  }
  const auto& points = nodes_.points();
  mesh.nodes.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (std::size_t n = 0; n < points.size(); ++n) mesh.nodes.row(n) = points[n];
  compute_polyhedral_geometry(mesh);
  result.grid_cells = grid_.cells;
  result.cell_size = grid_.cell_size;
  return result;
}

void check_options(const SlicingOptions& options) {
  if (options.cell_size < 0 || (options.cell_size == 0 && options.resolution < 1))
    throw InputError("slicing: resolution must be >= 1 or cell_size > 0");
  if (!(options.margin_cells >= 0)) throw InputError("slicing: margin must be >= 0 cells");
  if (!(options.sliver_fraction >= 0 && options.sliver_fraction < 1))
    throw InputError("slicing: sliver fraction must be in [0, 1)");
  if (options.octree_levels < 0 || options.octree_levels > 10) throw InputError("slicing: octree levels must be in 0..10");
}

double cell_size_for(const SlicingOptions& options, const Eigen::Vector3d& lower, const Eigen::Vector3d& upper) {
  return options.cell_size > 0 ? options.cell_size : (upper - lower).maxCoeff() / options.resolution;
}

}  // namespace

SlicedMesh slice_into_polyhedra(const SurfaceMesh& surface, const SlicingOptions& options) {
  check_options(options);
  if (surface.triangles.rows() == 0) throw InputError("slicing: the surface has no triangles");
  const Eigen::Vector3d lower = surface.vertices.colwise().minCoeff(), upper = surface.vertices.colwise().maxCoeff();
  const SlicingGrid grid = SlicingGrid::covering(lower, upper, cell_size_for(options, lower, upper), options.margin_cells);
  Slicer slicer(surface, grid);
  SlicedMesh result = slicer.run();
  if (options.octree_levels > 0)
    result.coarse_cells = grade_interior_hexahedra(result.mesh, grid.cells, slicer.grid_hexahedra(), options.octree_levels);
  if (options.sliver_fraction > 0)
    result.merged_slivers = merge_slivers(result.mesh, options.sliver_fraction * std::pow(grid.cell_size, 3));
  return result;
}

SlicedMesh slice_into_polyhedra(const AnalyticShape& shape, const SlicingOptions& options) {
  check_options(options);
  const Eigen::AlignedBox3d box = shape.bounding_box();
  const double cell_size = cell_size_for(options, box.min(), box.max());
  const SurfaceMesh surface = boundary_surface(tetrahedralize_shape(shape, cell_size / 2)).surface;
  SlicingOptions surface_options = options;
  surface_options.cell_size = cell_size;
  return slice_into_polyhedra(surface, surface_options);
}

}  // namespace altfem
