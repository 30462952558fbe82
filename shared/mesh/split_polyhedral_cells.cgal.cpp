#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

#include "shared/common/error.hpp"
#include "shared/mesh/convex_cell.hpp"
#include "shared/mesh/split_polyhedral_cells.hpp"

namespace altfem {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactPoint = Kernel::Point_3;
using ExactPlane = Kernel::Plane_3;
using Loop = std::vector<int>;
// The nodes already made in one face, one cell's inside or on one edge: a crossing
// constructed again (from the other side of a chord, or by a neighbour) is found here.
using Made = std::vector<std::pair<ExactPoint, int>>;

// A piece of a split cell: 8 × cell + the bit set of the cell's planes it lies in front of.
constexpr int max_planes = 3;
// A node this fraction of the mesh's diagonal off a split plane lies on it (as
// cut_polyhedral_mesh takes nodes on its blade): no piece is thinner.
constexpr double snap_fraction = 1e-12;
int piece_key(int cell, int mask) { return (cell << max_planes) | mask; }

ExactPoint to_exact(const Eigen::Vector3d& x) { return {x.x(), x.y(), x.z()}; }

class CellSplitter {
public:
  CellSplitter(const PolyhedralMesh& mesh, const std::vector<CellSplit>& splits) : mesh_(mesh) {
    cell_planes_.resize(static_cast<std::size_t>(mesh.cell_count()));
    for (Eigen::Index node = 0; node < mesh.nodes.rows(); ++node) {
      points_.push_back(to_exact(mesh.nodes.row(node)));
      positions_.push_back(mesh.nodes.row(node));
    }
    snap_ = snap_fraction * (mesh.nodes.colwise().maxCoeff() - mesh.nodes.colwise().minCoeff()).norm();
    std::map<std::array<double, 4>, int> plane_ids;  // equal planes shared, so their crossings are one node
    for (const CellSplit& split : splits) {
      if (split.cell < 0 || split.cell >= mesh.cell_count())
        throw std::invalid_argument("split_polyhedral_cells: no cell " + std::to_string(split.cell));
      if (split.planes.empty() || split.planes.size() > max_planes || !cell_planes_[split.cell].empty())
        throw std::invalid_argument("split_polyhedral_cells: cell " + std::to_string(split.cell) +
                                    " needs 1 to 3 planes, listed once");
      for (const SplitPlane& plane : split.planes) {
        if (!(plane.normal.squaredNorm() > 0))
          throw std::invalid_argument("split_polyhedral_cells: a plane of cell " + std::to_string(split.cell) +
                                      " has a zero normal");
        const std::array<double, 4> key{plane.normal.x(), plane.normal.y(), plane.normal.z(), plane.offset};
        const auto [found, inserted] = plane_ids.emplace(key, static_cast<int>(planes_.size()));
        if (inserted) {
          planes_.emplace_back(key[0], key[1], key[2], -key[3]);
          unit_normals_.push_back(plane.normal.normalized());
          unit_offsets_.push_back(plane.offset / plane.normal.norm());
        }
        cell_planes_[split.cell].push_back(found->second);
      }
      if (!is_convex_cell(mesh, split.cell, cell_node_set(mesh, split.cell)))
        throw std::invalid_argument("split_polyhedral_cells: cell " + std::to_string(split.cell) + " is not convex");
    }
  }

  SplitCells run() {
    insert_edge_crossings();
    face_pieces_.resize(static_cast<std::size_t>(mesh_.face_count()));
    for (int face = 0; face < mesh_.face_count(); ++face) split_face(face);
    for (int cell = 0; cell < mesh_.cell_count(); ++cell)
      for (std::size_t plane = 0; plane < cell_planes_[cell].size(); ++plane) add_sections(cell, plane);
    return assemble();
  }

private:
  // A node within `snap_` of a plane lies on it; otherwise the exact side. Neighbours split
  // 1→2 by the planes normal to nearly equal principal directions cross a shared edge a few
  // ulps apart: taken exactly, that is two nodes and faces a few ulps wide.
  int side(int node, int plane) const {
    if (std::abs(unit_normals_[plane].dot(positions_[node]) - unit_offsets_[plane]) <= snap_) return 0;
    return static_cast<int>(planes_[plane].oriented_side(points_[node]));
  }

  // The midpoints of a constructed point's interval approximation (of its exact value's
  // once that is evaluated), and whether they are within `accuracy` of it.
  static std::pair<Eigen::Vector3d, bool> approximate_position(const ExactPoint& point, double accuracy) {
    const auto& approximation = CGAL::approx(point);
    Eigen::Vector3d position;
    bool within = true;
    for (int axis = 0; axis < 3; ++axis) {
      const auto& coordinate = approximation[axis];
      position[axis] = CGAL::to_double(coordinate);
      within = within && coordinate.sup() - coordinate.inf() <= 2 * accuracy;
    }
    return {position, within};
  }

  // The node at `point`, made once per context: the same point, or one within `snap_` of it.
  // The rounded distance is asked first: a crossing made again (from the other side of a
  // chord) is the same point, which the exact comparison can only confirm by evaluating
  // both constructions exactly (rational arithmetic, most of the split's time under `perf`),
  // while their approximations agree far inside `snap_`; points farther apart than that are
  // told apart by the comparison's interval filter. A new node is placed at its exact value,
  // rounded (one exact evaluation per node): the pieces' faces must be planar to 1e-10 of
  // their size for the next split's convexity check (convex_cell.cpp), thin faces included.
  int node_at(const ExactPoint& point, Made& made) {
    auto [position, within] = approximate_position(point, 0.1 * snap_);
    if (!within) {  // an ill-conditioned construction: CGAL's to_double settles for a relative 1e-5
      CGAL::exact(point);
      position = approximate_position(point, 0.1 * snap_).first;
    }
    for (const auto& [existing, node] : made)
      if ((positions_[node] - position).norm() <= snap_ || existing == point) return node;
    CGAL::exact(point);  // refines the approximation to the exact value's rounding
    points_.push_back(point);
    positions_.push_back(approximate_position(point, 0).first);
    const int node = static_cast<int>(points_.size()) - 1;
    made.emplace_back(point, node);
    return node;
  }

  int crossing(int first, int second, int plane, Made& made) {
    const auto result = CGAL::intersection(Kernel::Line_3(points_[first], points_[second]), planes_[plane]);
    const ExactPoint* point = result ? boost::get<ExactPoint>(&*result) : nullptr;
    if (point == nullptr)
      throw std::logic_error("split_polyhedral_cells: an edge with ends on either side is parallel");
    return node_at(*point, made);
  }

  // Step 1: each edge of a split cell gets the crossings of that cell's planes, and every
  // face holding the edge gets them as nodes, in order along it (hanging nodes included).
  void insert_edge_crossings() {
    std::map<std::pair<int, int>, Made> edge_nodes;
    // An edge's crossing with one plane is made once: its other faces and the neighbours
    // that share the plane would construct the same point again, and comparing equal lazy
    // points computes both exactly.
    std::set<std::array<int, 3>> crossed;
    for (int cell = 0; cell < mesh_.cell_count(); ++cell)
      for (const int plane : cell_planes_[cell])
        for (const int face : mesh_.cell_faces[cell]) {
          const Loop& loop = mesh_.faces[face];
          for (std::size_t k = 0; k < loop.size(); ++k) {
            const int a = std::min(loop[k], loop[(k + 1) % loop.size()]);
            const int b = std::max(loop[k], loop[(k + 1) % loop.size()]);
            if (side(a, plane) * side(b, plane) < 0 && crossed.insert({a, b, plane}).second)
              crossing(a, b, plane, edge_nodes[{a, b}]);
          }
        }
    for (auto& [edge, made] : edge_nodes)
      std::sort(made.begin(), made.end(), [&, from = points_[edge.first]](const auto& p, const auto& q) {
        return CGAL::compare_distance_to_point(from, p.first, q.first) == CGAL::SMALLER;
      });
    loops_.resize(static_cast<std::size_t>(mesh_.face_count()));
    for (int face = 0; face < mesh_.face_count(); ++face) {
      const Loop& loop = mesh_.faces[face];
      for (std::size_t k = 0; k < loop.size(); ++k) {
        const int a = loop[k], b = loop[(k + 1) % loop.size()];
        loops_[face].push_back(a);
        const auto found = edge_nodes.find({std::min(a, b), std::max(a, b)});
        if (found == edge_nodes.end()) continue;
        const std::size_t start = loops_[face].size();
        for (const auto& [point, node] : found->second) loops_[face].push_back(node);
        if (a > b) std::reverse(loops_[face].begin() + static_cast<std::ptrdiff_t>(start), loops_[face].end());
      }
    }
  }

  // The convex `loop` split by `plane`: its pieces in front of and behind it, or the loop
  // whole when the plane does not cross it.
  std::vector<Loop> split_loop(const Loop& loop, int plane, Made& made) {
    std::vector<int> sides;
    for (const int node : loop) sides.push_back(side(node, plane));
    const bool in_front = std::count(sides.begin(), sides.end(), 1) > 0;
    const bool behind = std::count(sides.begin(), sides.end(), -1) > 0;
    if (!in_front || !behind) return {loop};
    Loop front, back;
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const std::size_t next = (k + 1) % loop.size();
      if (sides[k] >= 0) front.push_back(loop[k]);
      if (sides[k] <= 0) back.push_back(loop[k]);
      if (sides[k] * sides[next] < 0) {
        const int node = crossing(loop[k], loop[next], plane, made);
        front.push_back(node);
        back.push_back(node);
      }
    }
    return {front, back};
  }

  std::vector<Loop> split_by_planes(std::vector<Loop> pieces, const std::vector<int>& planes, Made& made) {
    for (const int plane : planes) {
      std::vector<Loop> split;
      for (const Loop& piece : pieces)
        for (Loop& part : split_loop(piece, plane, made)) split.push_back(std::move(part));
      pieces = std::move(split);
    }
    return pieces;
  }

  // Step 2: a face of a split cell, split by the planes of the cells on both its sides.
  void split_face(int face) {
    std::vector<int> planes;
    for (int end = 0; end < 2; ++end)
      if (const int cell = mesh_.face_cells(face, end); cell >= 0)
        planes.insert(planes.end(), cell_planes_[cell].begin(), cell_planes_[cell].end());
    std::sort(planes.begin(), planes.end());
    planes.erase(std::unique(planes.begin(), planes.end()), planes.end());
    Made made;
    face_pieces_[face] = split_by_planes({loops_[face]}, planes, made);
  }

  // The side of `plane` a piece lies on (after every split, its nodes are on one side or
  // on the plane): the first non-zero side of its nodes, 0 when it lies in the plane.
  int side_of_piece(const Loop& loop, int plane) const {
    for (const int node : loop)
      if (const int sign = side(node, plane); sign != 0) return sign;
    return 0;
  }

  // The planes of `cell` that `loop` lies in front of, as a bit set; plane number `skip`
  // (the one a section lies in) left out.
  int mask_of(const Loop& loop, int cell, std::size_t skip = max_planes) const {
    int mask = 0;
    const std::vector<int>& planes = cell_planes_[cell];
    for (std::size_t k = 0; k < planes.size(); ++k) {
      if (k == skip) continue;
      const int sign = side_of_piece(loop, planes[k]);
      if (sign == 0)
        throw NumericalError("refine: a face of cell " + std::to_string(cell) + " lies in one of its split planes");
      if (sign > 0) mask |= 1 << k;
    }
    return mask;
  }

  int key_of(const Loop& loop, int cell) const {
    return cell < 0 ? -1 : piece_key(cell, cell_planes_[cell].empty() ? 0 : mask_of(loop, cell));
  }

  // Step 3: the section of `cell` by its plane number `index` (its boundary the reversed
  // edges in that plane of the face pieces in front of it, so the loop is oriented out of
  // the front pieces), split by the cell's other planes into the faces between its pieces.
  void add_sections(int cell, std::size_t index) {
    const int plane = cell_planes_[cell][index];
    std::map<std::pair<int, int>, int> edges;  // directed edge → count
    for (const int face : mesh_.cell_faces[cell])
      for (Loop piece : face_pieces_[face]) {
        if (mesh_.face_cells(face, 0) != cell) std::reverse(piece.begin(), piece.end());
        if (!(mask_of(piece, cell) & (1 << index))) continue;
        for (std::size_t k = 0; k < piece.size(); ++k) {
          const int a = piece[k], b = piece[(k + 1) % piece.size()];
          if (side(a, plane) == 0 && side(b, plane) == 0) ++edges[{a, b}];
        }
      }
    std::map<int, int> next;  // the section's edges: reversed, those not matched inside the front pieces
    for (const auto& [edge, count] : edges)
      if (!edges.contains({edge.second, edge.first})) next[edge.second] = edge.first;
    if (next.size() < 3) return;  // the plane only touches the cell
    Loop section{next.begin()->first};
    while (section.size() <= next.size()) {
      const auto found = next.find(section.back());
      if (found == next.end()) break;
      if (found->second == section.front()) break;
      section.push_back(found->second);
    }
    if (section.size() != next.size())
      throw NumericalError("refine: the section of cell " + std::to_string(cell) + " by a split plane is not one loop");
    std::vector<int> others;
    for (std::size_t k = 0; k < cell_planes_[cell].size(); ++k)
      if (k != index) others.push_back(cell_planes_[cell][k]);
    Made& made = cell_points_[cell];
    for (const Loop& piece : split_by_planes({section}, others, made)) {
      const int mask = mask_of(piece, cell, index);
      section_faces_.push_back({piece, piece_key(cell, mask | (1 << index)), piece_key(cell, mask)});
    }
  }

  struct Face {
    Loop loop;
    int owner, neighbour;  // piece keys; neighbour −1 on the boundary
  };

  SplitCells assemble() {
    std::vector<Face> faces;
    for (int face = 0; face < mesh_.face_count(); ++face)
      for (const Loop& piece : face_pieces_[face])
        faces.push_back({piece, key_of(piece, mesh_.face_cells(face, 0)), key_of(piece, mesh_.face_cells(face, 1))});
    faces.insert(faces.end(), section_faces_.begin(), section_faces_.end());

    // Cell numbers: an unsplit cell and a split cell's first piece keep the input's.
    std::map<int, int> cell_of_key;
    SplitCells result;
    for (const Face& face : faces)
      for (const int key : {face.owner, face.neighbour})
        if (key >= 0) cell_of_key.emplace(key, -1);
    result.parent_cell.resize(static_cast<std::size_t>(mesh_.cell_count()));
    std::vector<int> appended;
    std::vector<bool> numbered(static_cast<std::size_t>(mesh_.cell_count()), false);
    for (auto& [key, number] : cell_of_key) {  // in key order: by cell, then by piece
      const int cell = key >> max_planes;
      if (!numbered[cell]) {
        numbered[cell] = true;
        number = cell;
        result.parent_cell[cell] = cell;
      } else {
        number = mesh_.cell_count() + static_cast<int>(appended.size());
        appended.push_back(cell);
      }
    }
    result.parent_cell.insert(result.parent_cell.end(), appended.begin(), appended.end());

    PolyhedralMesh& mesh = result.mesh;
    const int cell_count = static_cast<int>(result.parent_cell.size());
    mesh.cell_faces.resize(static_cast<std::size_t>(cell_count));
    std::vector<std::vector<int>> loops;
    std::vector<std::array<int, 2>> face_cells;
    for (auto& face : faces) {
      face_cells.push_back({cell_of_key.at(face.owner), face.neighbour < 0 ? -1 : cell_of_key.at(face.neighbour)});
      loops.push_back(std::move(face.loop));
    }
    set_faces(mesh, std::move(loops), face_cells);
    mesh.nodes.resize(static_cast<Eigen::Index>(points_.size()), 3);
    mesh.nodes.topRows(mesh_.nodes.rows()) = mesh_.nodes;
    for (std::size_t node = static_cast<std::size_t>(mesh_.nodes.rows()); node < points_.size(); ++node)
      mesh.nodes.row(static_cast<Eigen::Index>(node)) = positions_[node];
    for (int cell = 0; cell < cell_count; ++cell)
      mesh.cell_kinds.push_back(piece_kind(mesh, cell, result.parent_cell[cell]));

    for (int cell = 0; cell < mesh_.cell_count(); ++cell) result.split_cells += cell_planes_[cell].empty() ? 0 : 1;
    result.new_nodes = static_cast<int>(mesh.nodes.rows() - mesh_.nodes.rows());
    std::vector<bool> hanging(static_cast<std::size_t>(mesh.nodes.rows()), false);
    for (int cell = 0; cell < mesh_.cell_count(); ++cell)
      if (cell_planes_[cell].empty())
        for (const int face : mesh.cell_faces[cell])
          for (const int node : mesh.faces[face])
            if (node >= mesh_.nodes.rows()) hanging[node] = true;
    result.hanging_nodes = static_cast<int>(std::count(hanging.begin(), hanging.end(), true));
    compute_polyhedral_geometry(mesh);
    return result;
  }

  // A piece keeps its parent's kind when it has the parent's shape (a hexahedron's eighth:
  // 6 quadrilaterals on 8 nodes, which the harmonic method's trilinear basis serves).
  PolyhedralCellKind piece_kind(const PolyhedralMesh& mesh, int cell, int parent) const {
    const PolyhedralCellKind kind = mesh_.cell_kinds[parent];
    if (cell_planes_[parent].empty()) return kind;
    const int corners = kind == PolyhedralCellKind::tetrahedron ? 3 : 4;
    const std::size_t faces = kind == PolyhedralCellKind::tetrahedron ? 4 : 6;
    const bool same_shape = mesh.cell_faces[cell].size() == faces &&
                            std::all_of(mesh.cell_faces[cell].begin(), mesh.cell_faces[cell].end(),
                                        [&](int face) { return static_cast<int>(mesh.faces[face].size()) == corners; });
    const bool plain = kind == PolyhedralCellKind::tetrahedron || kind == PolyhedralCellKind::hexahedron;
    return plain && same_shape ? kind : PolyhedralCellKind::refined;
  }

  const PolyhedralMesh& mesh_;
  std::vector<ExactPlane> planes_;
  std::vector<Eigen::Vector3d> unit_normals_;  // per plane, for the snap
  std::vector<double> unit_offsets_;
  std::vector<Eigen::Vector3d> positions_;  // per node, rounded
  double snap_ = 0;
  std::vector<std::vector<int>> cell_planes_;   // per input cell, its planes (empty: not split)
  std::vector<ExactPoint> points_;              // per node, as constructed
  std::vector<Loop> loops_;                     // per input face, with the edge crossings
  std::vector<std::vector<Loop>> face_pieces_;  // per input face
  std::map<int, Made> cell_points_;             // per split cell, the nodes inside it
  std::vector<Face> section_faces_;
};

}  // namespace

SplitCells split_polyhedral_cells(const PolyhedralMesh& mesh, const std::vector<CellSplit>& splits) {
  return CellSplitter(mesh, splits).run();
}

}  // namespace altfem
