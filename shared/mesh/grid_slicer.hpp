#pragma once
// The grid slicer behind slice_into_polyhedra (internal to altfem_mesh): one pass over a
// surface and a grid that splits the surface into the grid cells, classifies the uncut
// cells, computes every grid face's region inside the object once (grid_face_region) and
// assembles the PolyhedralMesh (grid_slicer_assembly.cpp).
#include <array>
#include <string>
#include <unordered_map>
#include <vector>

#include "shared/common/error.hpp"
#include "shared/mesh/grid_face_region.hpp"
#include "shared/mesh/slice_into_polyhedra.hpp"
#include "shared/mesh/slicing_grid.hpp"

namespace altfem {

/// The surface lies in a grid plane where the slicer cannot tell the two sides' faces
/// apart (material near both sides, or a cell wholly inside next to a face the surface
/// only partly covers): slice_into_polyhedra moves the grid and slices again.
class SurfaceInGridPlane : public NumericalError {
public:
  using NumericalError::NumericalError;
};

/// A grid face: the plane x_axis = planes[axis][node(axis)], from grid node `node` over
/// one cell along the two other axes. Its lower cell is node − e_axis, its upper cell node.
struct GridFace {
  int axis;
  Eigen::Vector3i node;
};

class GridSlicer {
public:
  using Loops = std::vector<std::vector<int>>;
  using Segments = std::vector<std::array<int, 2>>;

  GridSlicer(const SurfaceMesh& surface, const SlicingGrid& grid) : surface_(surface), grid_(grid) {}

  /// The sliced mesh: hexahedra, one cell per connected piece of each cut grid cell; its
  /// geometry arrays are not computed yet.
  SlicedMesh run();
  /// After run(): per grid cell, the mesh cell of the hexahedron filling it, or −1.
  const std::vector<int>& grid_hexahedra() const { return grid_hexahedra_; }

private:
  enum class CellState : signed char { outside, inside, cut };
  /// A grid face of a cut cell that the surface does not cross.
  struct UndeterminedFace {
    GridFace face;
    bool both_cut;
    double towards_cut_cell;  ///< −1 or +1 along e_axis
  };

  bool is_cut(int cell) const { return !cell_pieces_[cell].empty(); }
  bool has_material(int cell) const { return cell >= 0 && state_[cell] != CellState::outside; }
  int cell_at(Eigen::Vector3i cell) const {
    for (int axis = 0; axis < 3; ++axis)
      if (cell(axis) < 0 || cell(axis) >= grid_.cells(axis)) return -1;
    return grid_.cell_index(cell);
  }
  long long face_key(const GridFace& face) const {
    const Eigen::Vector3i nodes = grid_.cells.array() + 1;
    return face.axis +
           3LL * (face.node(0) + nodes(0) * (face.node(1) + static_cast<long long>(nodes(1)) * face.node(2)));
  }
  int lower_cell(const GridFace& face) const {
    Eigen::Vector3i cell = face.node;
    --cell(face.axis);
    return cell_at(cell);
  }
  int upper_cell(const GridFace& face) const { return cell_at(face.node); }
  std::string face_name(const GridFace& face) const {
    return std::string("grid face ") + "xyz"[face.axis] + " = " +
           std::to_string(grid_.planes[face.axis][face.node(face.axis)]) + " at grid node (" +
           std::to_string(face.node(0)) + ", " + std::to_string(face.node(1)) + ", " + std::to_string(face.node(2)) +
           ")";
  }
  /// The node at a grid point, registered on first use (cached: faces ask for corners often).
  int grid_node(const Eigen::Vector3i& node) {
    const Eigen::Vector3i points = grid_.cells.array() + 1;
    int& id = grid_node_ids_[node(0) + points(0) * (node(1) + static_cast<std::size_t>(points(1)) * node(2))];
    if (id < 0) id = nodes_.node(grid_.grid_node(node));
    return id;
  }

  /// The corners counter-clockwise seen along +e_axis (outward for the lower cell).
  std::array<int, 4> corners_up(const GridFace& face) {
    const int b = (face.axis + 1) % 3, c = (face.axis + 2) % 3;
    const Eigen::Vector3i eb = Eigen::Vector3i::Unit(b), ec = Eigen::Vector3i::Unit(c);
    return {grid_node(face.node), grid_node(face.node + eb), grid_node(face.node + eb + ec), grid_node(face.node + ec)};
  }

  /// Uncut cells are wholly inside or outside: their centres decide (a centre is never on
  /// the surface, which does not enter an uncut cell).
  void classify_uncut_cells();
  /// Per cut cell and local face (2·axis + upper), the open edges of its surface pieces
  /// that lie on that face, reversed: the segments grid_face_region chains.
  void collect_open_edges(const SurfacePieces& pieces);
  static long long edge_key(int a, int b);
  static Eigen::Vector3d outward_normal(int local_face);
  /// The region of one grid face from one of its cut cells, its loops and holes oriented
  /// along +e_axis.
  GridFaceRegion region_from(const GridFace& face, int cell, bool cell_is_lower);
  static Loops canonical(Loops loops);
  /// Every grid face of a cut cell gets its loops (oriented along +e_axis) once.
  void compute_face_regions();
  /// Wholly inside or outside: the face centre decides, or, when the surface lies in the
  /// face's plane there (the centre is on it), a point just inside the cut cell.
  void decide_undetermined_faces(const std::vector<UndeterminedFace>& faces);
  /// Next to a cell wholly inside, the cut cell's face region must be the whole face.
  void check_next_to_inside_cell(const GridFace& face, const Loops& loops, int other_cell, bool both_cut);
  SlicedMesh assemble(const SurfacePieces& pieces);

  const SurfaceMesh& surface_;
  const SlicingGrid& grid_;
  NodeRegistry nodes_;
  std::vector<std::vector<int>> cell_pieces_;  ///< per grid cell, its surface pieces
  std::vector<CellState> state_;
  std::unordered_map<int, std::array<Segments, 6>> face_segments_;
  std::unordered_map<long long, Loops> regions_;  ///< grid faces of cut cells → loops along +e_axis
  std::vector<int> grid_hexahedra_;
  std::vector<int> grid_node_ids_;  ///< per grid point, its node or −1
};

}  // namespace altfem
