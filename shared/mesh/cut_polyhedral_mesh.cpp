#include "shared/mesh/cut_polyhedral_mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <utility>

#include "shared/common/error.hpp"
#include "shared/mesh/convex_cell.hpp"
#include "shared/mesh/cut_by_surface.hpp"
#include "shared/mesh/cut_polyhedral_pieces.hpp"
#include "shared/mesh/disjoint_sets.hpp"
#include "shared/mesh/planar_loops.hpp"
#include "shared/mesh/split_holes.hpp"

namespace altfem {
namespace {

// Of the mesh's bounding-box diagonal: a few hundred ulps, far below any element.
constexpr double snap_fraction = 1e-13;

// A face a split step cannot split (a cluster of nodes a few ulps apart whose rounded
// positions cross the plane more than twice): its cells are kept whole and the step is
// made again.
struct UnsplittableFace : NumericalError {
  UnsplittableFace(const std::string& what, int cell0, int cell1) : NumericalError(what), cells{cell0, cell1} {}
  std::array<int, 2> cells;
};

class CutBuilder {
public:
  /// `whole`: per cell, kept whole by a split step (empty: none).
  CutBuilder(const PolyhedralMesh& mesh, const CuttingPlane& plane, bool compute_geometry, const CutScope& scope,
             std::vector<bool> whole = {})
      : mesh_(mesh),
        blade_(plane),
        piece_at_(plane.piece_at),
        scope_(scope),
        whole_(std::move(whole)),
        compute_geometry_(compute_geometry) {
    nodes_.reserve(mesh.nodes.rows());
    for (Eigen::Index n = 0; n < mesh.nodes.rows(); ++n) {
      nodes_.push_back(mesh.nodes.row(n));
      sources_.push_back({static_cast<int>(n), static_cast<int>(n), 0.0});
    }
    // A node closer to the blade than this is taken on it, so no piece is thinner
    // (Kaufmann et al. 2009 §9.4 merge negligible pieces; these would have faces of no
    // area once their crossing nodes are rounded). Nodes do not move: the volume stays.
    const double snap_distance =
        scope.snap ? snap_fraction * (mesh.nodes.colwise().maxCoeff() - mesh.nodes.colwise().minCoeff()).norm() : 0.0;
    const Eigen::Vector3d unit_normal = blade_.normal.normalized();
    side_.resize(nodes_.size());
    for (std::size_t n = 0; n < nodes_.size(); ++n) {
      side_[n] = blade_.side(nodes_[n]);
      if (side_[n] != 0 && std::abs((nodes_[n] - blade_.a).dot(unit_normal)) <= snap_distance) {
        side_[n] = 0;
        ++snapped_;
      }
    }
    // A surface blade's step names nodes an earlier step made on its plane.
    if (scope.on_plane)
      for (const int node : *scope.on_plane)
        if (side_[node] != 0) {
          side_[node] = 0;
          ++snapped_;
        }
  }

  PolyhedralCut build() {
    classify_cells();
    for (int face = 0; face < mesh_.face_count(); ++face) split_face(face);
    if (scope_.action == CutAction::split) add_crossings_to_whole_faces();
    std::vector<int> without_section;
    for (int cell = 0; cell < mesh_.cell_count(); ++cell) {
      if (!crossed_[cell]) continue;
      if (!cap_covered_[cell]) {
        try {
          close_caps(cell, +1, true);
        } catch (const NumericalError&) {
          // A sliver a split step reaches can have nodes strictly on both sides and no
          // section that closes (its rounded nodes do not make it convex): it stays whole.
          if (scope_.action != CutAction::split) throw;
          without_section.push_back(cell);
        }
        continue;
      }
      for (const int sigma : {+1, -1}) close_caps(cell, sigma, false);
    }
    if (!without_section.empty()) rejoin_halves(without_section);
    return assemble();
  }

private:
  std::vector<int> nodes_of(int cell) const { return cell_node_set(mesh_, cell); }

  bool has_both_sides(const std::vector<int>& loop) const {
    bool positive = false, negative = false;
    for (const int node : loop) {
      positive |= side_[node] > 0;
      negative |= side_[node] < 0;
    }
    return positive && negative;
  }

  // Whether the blade covers the section of `cell` by its plane: every node of the cell
  // on the plane and every point where the plane crosses one of its edges.
  bool covers_section(int cell) {
    if (blade_.whole_plane()) return true;
    for (const int face : mesh_.cell_faces[cell]) {
      const std::vector<int>& loop = mesh_.faces[face];
      for (std::size_t k = 0; k < loop.size(); ++k) {
        const int u = loop[k], v = loop[(k + 1) % loop.size()];
        if (side_[u] == 0 && !blade_.covers(nodes_[u])) return false;
        if (side_[u] * side_[v] >= 0) continue;
        const auto key = std::minmax(u, v);
        auto found = crossing_covered_.find(key);
        if (found == crossing_covered_.end())
          found = crossing_covered_.emplace(key, blade_.covers_crossing(nodes_[key.first], nodes_[key.second])).first;
        if (!found->second) return false;
      }
    }
    return true;
  }

  // Whether the scope lets the blade split `cell`: a split step only splits the cells in its
  // region, a separate step none.
  bool in_scope(int cell) const {
    if (!scope_.region) return true;
    Eigen::AlignedBox3d box;
    for (const int node : nodes_of(cell)) box.extend(nodes_[node]);
    return box.intersects(*scope_.region);
  }

  // A split step's crossing nodes on the edges of faces it left whole (those of cells out
  // of its region next to split ones), so that each such cell's faces still meet edge to
  // edge; the cell keeps its volume and becomes of kind split.
  void add_crossings_to_whole_faces() {
    if (crossings_.empty()) return;
    for (CutFace& face : faces_) {
      if (!has_both_sides(face.loop)) continue;
      std::vector<int> augmented;
      for (std::size_t k = 0; k < face.loop.size(); ++k) {
        const int u = face.loop[k], v = face.loop[(k + 1) % face.loop.size()];
        augmented.push_back(u);
        if (side_[u] * side_[v] >= 0) continue;
        const auto found = crossings_.find(std::minmax(u, v));
        if (found != crossings_.end()) augmented.push_back(found->second);
      }
      if (augmented.size() == face.loop.size()) continue;
      face.loop = std::move(augmented);
      for (const int piece_index : {face.first, face.second})
        if (piece_index >= 0) touched_[parent_[piece_index]] = true;
    }
  }

  // Per cell, whether the blade may cut it: every cell, or with `piece_at` the cells
  // connected through faces to one holding the node nearest that point.
  std::vector<bool> cells_of_piece_at() const {
    const int cells = mesh_.cell_count();
    if (!piece_at_) return std::vector<bool>(cells, true);
    DisjointSets pieces(cells);
    int nearest = -1;
    double nearest_distance = 0;
    for (int face = 0; face < mesh_.face_count(); ++face) {
      if (mesh_.face_cells(face, 1) >= 0) pieces.join(mesh_.face_cells(face, 0), mesh_.face_cells(face, 1));
      for (const int node : mesh_.faces[face]) {
        const double distance = (nodes_[node] - *piece_at_).squaredNorm();
        if (nearest < 0 || distance < nearest_distance) std::tie(nearest, nearest_distance) = std::pair{node, distance};
      }
    }
    std::vector<bool> holds(cells, false), result(cells, false);
    for (int face = 0; face < mesh_.face_count(); ++face)
      if (std::find(mesh_.faces[face].begin(), mesh_.faces[face].end(), nearest) != mesh_.faces[face].end())
        for (const int side : {mesh_.face_cells(face, 0), mesh_.face_cells(face, 1)})
          if (side >= 0) holds[pieces.find(side)] = true;
    for (int cell = 0; cell < cells; ++cell) result[cell] = holds[pieces.find(cell)];
    return result;
  }

  // A cell with nodes on both sides is crossed when the blade covers its section or that
  // of a cell joined to it through faces the plane crosses: a face the plane crosses is
  // split for both of its cells, so the mesh stays conforming. A crossed cell whose section
  // the blade does not cover keeps its two pieces joined (a finite blade's edge runs
  // through it, or it lies beyond the edge): the cut ends at the last cell it covers.
  void classify_cells() {
    const int cells = mesh_.cell_count();
    crossed_.assign(cells, false);
    cap_covered_.assign(cells, false);
    cell_sigma_.assign(cells, +1);
    convex_.assign(cells, true);
    first_piece_.resize(cells);
    std::vector<bool> reached(cells, false);
    DisjointSets joined(cells);
    in_piece_ = cells_of_piece_at();
    for (int cell = 0; cell < cells; ++cell) {
      bool positive = false, negative = false;
      for (const int node : nodes_of(cell)) {
        positive |= side_[node] > 0;
        negative |= side_[node] < 0;
      }
      reached[cell] = positive && negative && in_piece_[cell] && scope_.action != CutAction::separate;
      cell_sigma_[cell] = negative && !positive ? -1 : +1;
      if (reached[cell] && scope_.action == CutAction::cut) cap_covered_[cell] = covers_section(cell);
      // A split step's region is where it starts: it spreads to every cell joined to one
      // there through faces the plane crosses with `spread`, else it splits only those.
      if (reached[cell] && scope_.action == CutAction::split) {
        const bool starts_here = in_scope(cell) && (whole_.empty() || !whole_[cell]);
        cap_covered_[cell] = scope_.spread && starts_here;
        reached[cell] = scope_.spread || starts_here;
      }
    }
    touched_.assign(cells, false);
    for (int face = 0; face < mesh_.face_count(); ++face)
      if (mesh_.face_cells(face, 1) >= 0 && has_both_sides(mesh_.faces[face]))
        joined.join(mesh_.face_cells(face, 0), mesh_.face_cells(face, 1));
    std::vector<bool> covered_group(cells, false);
    for (int cell = 0; cell < cells; ++cell)
      if (cap_covered_[cell]) covered_group[joined.find(cell)] = true;
    // A spreading split keeps whole every cell joined to one it must keep whole.
    if (!whole_.empty() && scope_.spread)
      for (int cell = 0; cell < cells; ++cell)
        if (whole_[cell]) covered_group[joined.find(cell)] = false;
    for (int cell = 0; cell < cells; ++cell) {
      first_piece_[cell] = static_cast<int>(parent_.size());
      parent_.push_back(cell);
      // A split step that does not spread splits every cell it reaches
      // (add_crossings_to_whole_faces keeps the mesh conforming), its pieces joined.
      crossed_[cell] =
          reached[cell] && ((scope_.action == CutAction::split && !scope_.spread) || covered_group[joined.find(cell)]);
      if (!crossed_[cell]) continue;
      convex_[cell] = is_convex_cell(mesh_, cell, nodes_of(cell));
      parent_.push_back(cell);
      ++crossed_count_;
      if (scope_.action == CutAction::split) cap_covered_[cell] = false;  // its pieces stay joined
      if (!cap_covered_[cell]) ++joined_count_;
    }
    cap_edges_.resize(parent_.size());
  }

  // The piece of `cell` on side `sigma`: a crossed cell has two (positive first).
  int piece(int cell, int sigma) const {
    if (cell < 0) return -1;
    return first_piece_[cell] + (crossed_[cell] && sigma < 0 ? 1 : 0);
  }

  // The node where the blade crosses edge (u, v), whose ends lie strictly on either side:
  // one per edge, shared by every face that holds it.
  int crossing_node(int u, int v) {
    const auto key = std::minmax(u, v);
    const auto found = crossings_.find(key);
    if (found != crossings_.end()) return found->second;
    const Eigen::Vector3d& p = nodes_[key.first];
    const Eigen::Vector3d& q = nodes_[key.second];
    const double dp = (p - blade_.a).dot(blade_.normal), dq = (q - blade_.a).dot(blade_.normal);
    // The sides were decided exactly; these rounded distances only place the node (and
    // may round to 0 for a node a hair off the blade).
    const double t = dp != dq ? std::clamp(dp / (dp - dq), 0.0, 1.0) : 0.5;
    nodes_.push_back(p + t * (q - p));
    sources_.push_back({key.first, key.second, t});
    side_.push_back(0);
    const int node = static_cast<int>(nodes_.size()) - 1;
    crossings_.emplace(key, node);
    return node;
  }

  // The cap of a piece holds the blade edges of its faces, traversed the other way.
  void add_cap_edges(int piece_index, const std::vector<int>& loop) {
    const std::size_t n = loop.size();
    for (std::size_t k = 0; k < n; ++k) {
      const int from = loop[k], to = loop[(k + 1) % n];
      if (side_[from] == 0 && side_[to] == 0) cap_edges_[piece_index].emplace_back(to, from);
    }
  }

  // The side of the blade a crossed cell's face in the blade's plane bounds: the one
  // the face's outward normal (for that cell, as `loop` runs) points away from. An
  // uncrossed cell lies on one side.
  int in_plane_sigma(int cell, const std::vector<int>& loop) const {
    if (cell < 0 || !crossed_[cell]) return cell < 0 ? +1 : cell_sigma_[cell];
    return loop_area_vector(loop, nodes_).dot(blade_.normal) > 0 ? -1 : +1;
  }

  // Whether the blade separates a face in its plane: all its nodes covered, or for a
  // separate step (whose faces lie inside the blade or outside it, split by its edges'
  // planes before) its centroid, which rounding does not put on the blade's edge.
  bool covers_face(const std::vector<int>& loop) const {
    if (scope_.action == CutAction::separate) {
      Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
      for (const int node : loop) centroid += nodes_[node];
      return blade_.covers(centroid / static_cast<double>(loop.size()));
    }
    return std::all_of(loop.begin(), loop.end(), [&](int node) { return blade_.covers(nodes_[node]); });
  }

  // A face of the pieces of cell0 and cell1 on sides sigma0 and sigma1 (the same but for
  // a crossed cell's face in the blade's plane).
  void add_face(std::vector<int> loop, int cell0, int cell1, int sigma0, int sigma1, bool opened = false) {
    const int first = piece(cell0, sigma0), second = piece(cell1, sigma1);
    if (crossed_[cell0]) add_cap_edges(first, loop);
    if (cell1 >= 0 && crossed_[cell1]) add_cap_edges(second, std::vector<int>(loop.rbegin(), loop.rend()));
    faces_.push_back({std::move(loop), first, second, sigma0, opened});
  }

  void split_face(int face) {
    const std::vector<int>& loop = mesh_.faces[face];
    const int cell0 = mesh_.face_cells(face, 0), cell1 = mesh_.face_cells(face, 1);
    bool positive = false, negative = false;
    for (const int node : loop) {
      positive |= side_[node] > 0;
      negative |= side_[node] < 0;
    }
    if (!positive && !negative) {  // in the plane: an interior face the blade covers separates
      const std::vector<int> reversed(loop.rbegin(), loop.rend());
      const int sigma0 = in_plane_sigma(cell0, loop), sigma1 = in_plane_sigma(cell1, reversed);
      if (cell1 >= 0 && in_piece_[cell0] && scope_.action != CutAction::split && covers_face(loop)) {
        ++separated_;
        add_face(loop, cell0, -1, sigma0, sigma0, true);
        add_face(reversed, cell1, -1, sigma1, sigma1, true);
      } else {
        add_face(loop, cell0, cell1, sigma0, sigma1);
      }
      return;
    }
    if (!(positive && negative) || !(crossed_[cell0] || (cell1 >= 0 && crossed_[cell1]))) {
      const int sigma = negative && !positive ? -1 : +1;
      add_face(loop, cell0, cell1, sigma, sigma);
      return;
    }
    // Crossed: the loop with its crossing nodes, then its pieces on either side. A convex
    // face has two nodes on the blade and a piece on each side: the runs between them.
    std::vector<int> augmented;
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const int u = loop[k], v = loop[(k + 1) % loop.size()];
      augmented.push_back(u);
      if (side_[u] * side_[v] < 0) augmented.push_back(crossing_node(u, v));
    }
    std::vector<std::size_t> on_blade;
    for (std::size_t k = 0; k < augmented.size(); ++k)
      if (side_[augmented[k]] == 0) on_blade.push_back(k);
    std::vector<PolygonPiece> pieces;
    if (on_blade.size() == 2) {
      for (const auto& [start, end] : {std::pair{on_blade[0], on_blade[1]}, std::pair{on_blade[1], on_blade[0]}}) {
        PolygonPiece& run = pieces.emplace_back();
        for (std::size_t k = start;; k = (k + 1) % augmented.size()) {
          run.loop.push_back(augmented[k]);
          if (k == end) break;
        }
        run.side = side_[run.loop[1]];
      }
    } else {
      try {
        pieces = split_polygon_by_plane(augmented, nodes_, side_, blade_.normal);
      } catch (const NumericalError& error) {
        const std::string what = "cut: face " + std::to_string(face) + " of cell " + std::to_string(cell0) +
                                 " crossed by the blade: " + error.what();
        if (scope_.action == CutAction::split) throw UnsplittableFace(what, cell0, cell1);
        throw NumericalError(what);
      }
    }
    for (PolygonPiece& piece : pieces) add_face(std::move(piece.loop), cell0, cell1, piece.side, piece.side);
  }

  // The caps of the pieces of `cell` on side `sigma`: the polygons their blade edges close
  // (several where a non-convex cell's section falls apart; an edge that two of its faces
  // hold both ways — where a face of it lies in the blade's plane — bounds none). Each is a
  // boundary face when the blade covers the section, else a face joining the pieces on the
  // two sides.
  void close_caps(int cell, int sigma, bool joined) {
    const int piece_index = piece(cell, sigma);
    std::vector<std::pair<int, int>> edges = std::move(cap_edges_[piece_index]);
    std::sort(edges.begin(), edges.end());
    std::vector<bool> cancelled(edges.size(), false);
    for (std::size_t e = 0; e < edges.size(); ++e) {
      if (cancelled[e]) continue;
      const auto [begin, end] =
          std::equal_range(edges.begin(), edges.end(), std::pair{edges[e].second, edges[e].first});
      for (auto it = begin; it != end; ++it)
        if (!cancelled[it - edges.begin()]) {
          cancelled[e] = cancelled[it - edges.begin()] = true;
          break;
        }
    }
    std::vector<std::pair<int, int>> kept;
    for (std::size_t e = 0; e < edges.size(); ++e)
      if (!cancelled[e]) kept.push_back(edges[e]);
    const Eigen::Vector3d outward = -sigma * blade_.normal;
    const std::string where = "cut: the blade's section of cell " + std::to_string(cell);
    std::vector<std::vector<int>> loops;
    try {
      loops = trace_planar_loops(kept, nodes_, outward);
    } catch (const NumericalError& error) {
      throw NumericalError(where + " is not made of closed polygons: " + error.what());
    }
    if (loops.empty()) throw NumericalError(where + " is empty");
    // One loop bounds the section whatever its rounded area; of several, one turning the
    // other way round bounds a hole (a cell that is a ring around the blade's path), which
    // a face cannot have: each hole is bridged to its outer loop, splitting the cap into
    // simple polygons on the same nodes.
    std::vector<std::vector<int>> outer, holes;
    for (std::vector<int>& loop : loops) {
      if (loop.size() < 3) throw NumericalError(where + " has a polygon of fewer than 3 corners");
      const bool hole = loops.size() > 1 && !(loop_area_vector(loop, nodes_).dot(outward) > 0);
      (hole ? holes : outer).push_back(std::move(loop));
    }
    if (!holes.empty())
      outer = split_holes(std::move(outer), holes, plane_coordinates(nodes_, outward),
                          where + " has holes that cannot be bridged");
    const int other_piece = joined ? piece(cell, -sigma) : -1;
    for (std::vector<int>& loop : outer) faces_.push_back({std::move(loop), piece_index, other_piece, sigma, !joined});
  }

  // The split cells without a section stay whole: each one's negative half's faces go to
  // its positive half, and the pieces after it move down.
  void rejoin_halves(const std::vector<int>& cells) {
    std::vector<bool> dropped(parent_.size(), false);
    for (const int cell : cells) {
      dropped[first_piece_[cell] + 1] = true;
      crossed_[cell] = false;
      touched_[cell] = true;
      --crossed_count_;
      --joined_count_;
    }
    std::vector<int> new_index(parent_.size());
    int next = 0;
    for (std::size_t piece_index = 0; piece_index < parent_.size(); ++piece_index)
      new_index[piece_index] = dropped[piece_index] ? next - 1 : next++;  // a dropped half: its positive half's
    for (CutFace& face : faces_) {
      face.first = new_index[face.first];
      if (face.second >= 0) face.second = new_index[face.second];
    }
    std::vector<int> parents;
    for (std::size_t piece_index = 0; piece_index < parent_.size(); ++piece_index)
      if (!dropped[piece_index]) parents.push_back(parent_[piece_index]);
    parent_ = std::move(parents);
    for (int& first : first_piece_) first = new_index[first];
  }

  // The nodes a copy of which each group of pieces apart around it needs: those of faces
  // the cut opened, and a covered node that cells on both sides touch without a face in
  // the plane (an earlier cut's slivers left out make such meshes).
  std::vector<bool> opened_nodes() const {
    std::vector<bool> opened_node(nodes_.size(), false);
    if (scope_.action == CutAction::split) return opened_node;
    std::vector<int> sides_using(nodes_.size(), 0);  // bit 1: positive, bit 2: negative
    for (const CutFace& face : faces_)
      for (const int node : face.loop) {
        opened_node[node] = opened_node[node] || face.opened;
        sides_using[node] |= face.sigma > 0 ? 1 : 2;
      }
    for (std::size_t node = 0; node < nodes_.size(); ++node)
      if (sides_using[node] == 3 && !opened_node[node] && side_[node] == 0)
        opened_node[node] = blade_.covers(nodes_[node]) ||
                            (sources_[node].weight > 0 &&
                             blade_.covers_crossing(nodes_[sources_[node].first], nodes_[sources_[node].second]));
    return opened_node;
  }

  PolyhedralCut assemble() {
    std::vector<bool> separates(parent_.size());
    std::vector<int> half_sigma(parent_.size());
    for (std::size_t half = 0; half < parent_.size(); ++half) {
      const int cell = parent_[half];
      separates[half] = crossed_[cell] && !convex_[cell];
      half_sigma[half] = !crossed_[cell] ? cell_sigma_[cell] : static_cast<int>(half) == first_piece_[cell] ? +1 : -1;
    }
    const CutPieces pieces = separate_disconnected_parts(faces_, parent_, half_sigma, separates);
    parent_ = pieces.parent;
    const int duplicated = duplicate_separated_nodes(faces_, opened_nodes(), pieces.sigma, nodes_, sources_);
    PolyhedralCut cut;
    PolyhedralMesh& result = cut.mesh;
    result.nodes.resize(static_cast<Eigen::Index>(nodes_.size()), 3);
    for (std::size_t node = 0; node < nodes_.size(); ++node)
      result.nodes.row(static_cast<Eigen::Index>(node)) = nodes_[node];
    result.face_cells.resize(static_cast<Eigen::Index>(faces_.size()), 2);
    result.cell_faces.resize(parent_.size());
    for (std::size_t f = 0; f < faces_.size(); ++f) {
      CutFace& face = faces_[f];
      result.faces.push_back(std::move(face.loop));
      result.face_cells(static_cast<Eigen::Index>(f), 0) = face.first;
      result.face_cells(static_cast<Eigen::Index>(f), 1) = face.second;
      result.cell_faces[face.first].push_back(static_cast<int>(f));
      if (face.second >= 0) result.cell_faces[face.second].push_back(static_cast<int>(f));
    }
    for (std::size_t piece_index = 0; piece_index < parent_.size(); ++piece_index) {
      const int cell = parent_[piece_index];
      const PolyhedralCellKind kind = mesh_.cell_kinds[cell];
      result.cell_kinds.push_back(!crossed_[cell]
                                      ? (touched_[cell] && convex_kind(kind) ? PolyhedralCellKind::split : kind)
                                  : convex_[cell] ? PolyhedralCellKind::split
                                                  : PolyhedralCellKind::cut);
    }
    if (compute_geometry_) {
      try {
        compute_polyhedral_geometry(result);
      } catch (const NumericalError&) {
        // Rare (a blade a few 1e-12 off nodes): only then are the pieces' volumes checked.
        std::vector<bool> is_piece(parent_.size());
        for (std::size_t piece_index = 0; piece_index < parent_.size(); ++piece_index)
          is_piece[piece_index] = crossed_[parent_[piece_index]];
        cut.merged_pieces = merge_pieces_without_volume(result, parent_, sources_, is_piece);
        if (cut.merged_pieces == 0) throw;
        compute_polyhedral_geometry(result);
      }
    }
    cut.parent_cell = parent_;
    cut.node_sources = std::move(sources_);
    cut.crossed_cells = crossed_count_;
    cut.separated_faces = separated_;
    cut.duplicated_nodes = duplicated;
    cut.snapped_nodes = snapped_;
    cut.joined_cells = joined_count_;
    return cut;
  }

  const PolyhedralMesh& mesh_;
  const ExactBlade blade_;
  const std::optional<Eigen::Vector3d> piece_at_;
  const CutScope scope_;
  const std::vector<bool> whole_;       ///< per input cell a split step keeps whole (empty: none)
  std::vector<bool> touched_;           ///< per input cell left whole: a split step added crossing nodes to its faces
  std::vector<bool> in_piece_;          ///< per input cell: the blade may cut it (piece_at)
  std::vector<Eigen::Vector3d> nodes_;  ///< the input's, then the crossing nodes, then the copies
  std::vector<NodeSource> sources_;     ///< per node of nodes_
  std::vector<int> side_;               ///< per node of nodes_ before the copies: −1, 0, +1
  std::vector<bool> crossed_;
  std::vector<bool> convex_;       ///< per input cell the blade crosses: whether it is convex
  std::vector<bool> cap_covered_;  ///< per input cell the plane crosses: the blade covers its section
  std::map<std::pair<int, int>, bool> crossing_covered_;  ///< per edge the plane crosses
  std::vector<int> cell_sigma_;   ///< the side of an uncrossed cell (+1 when it has no node off the blade)
  std::vector<int> first_piece_;  ///< per input cell, its first piece
  std::vector<int> parent_;       ///< per piece, its input cell
  std::map<std::pair<int, int>, int> crossings_;
  std::vector<std::vector<std::pair<int, int>>> cap_edges_;  ///< per piece: its cap's edges
  std::vector<CutFace> faces_;
  int crossed_count_ = 0, joined_count_ = 0, separated_ = 0, snapped_ = 0;
  bool compute_geometry_ = true;
};

}  // namespace

PolyhedralCut cut_polyhedral_mesh(const PolyhedralMesh& mesh, const CuttingPlane& plane, bool compute_geometry,
                                  const CutScope& scope) {
  if (plane.surface) return cut_polyhedral_mesh_by_surface(mesh, *plane.surface, compute_geometry);
  if (scope.action != CutAction::split) return CutBuilder(mesh, plane, compute_geometry, scope).build();
  std::vector<bool> whole(static_cast<std::size_t>(mesh.cell_count()), false);
  for (;;) {
    try {
      return CutBuilder(mesh, plane, compute_geometry, scope, whole).build();
    } catch (const UnsplittableFace& face) {
      for (const int cell : face.cells)
        if (cell >= 0) {
          if (whole[cell]) throw;
          whole[cell] = true;
        }
    }
  }
}

}  // namespace altfem
