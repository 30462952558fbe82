#include "shared/mesh/cut_polyhedral_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <utility>

#include "shared/common/error.hpp"
#include "shared/mesh/convex_cell.hpp"
#include "shared/mesh/disjoint_sets.hpp"

namespace altfem {
namespace {

// Of the mesh's bounding-box diagonal: a few hundred ulps, far below any element.
constexpr double snap_fraction = 1e-13;

class CutBuilder {
public:
  CutBuilder(const PolyhedralMesh& mesh, const CuttingPlane& plane, bool compute_geometry)
      : mesh_(mesh), blade_(plane), piece_at_(plane.piece_at), compute_geometry_(compute_geometry) {
    nodes_.reserve(mesh.nodes.rows());
    for (Eigen::Index n = 0; n < mesh.nodes.rows(); ++n) {
      nodes_.push_back(mesh.nodes.row(n));
      sources_.push_back({static_cast<int>(n), static_cast<int>(n), 0.0});
    }
    // A node closer to the blade than this is taken on it, so no piece is thinner
    // (Kaufmann et al. 2009 §9.4 merge negligible pieces; these would have faces of no
    // area once their crossing nodes are rounded). Nodes do not move: the volume stays.
    const double snap_distance =
        snap_fraction * (mesh.nodes.colwise().maxCoeff() - mesh.nodes.colwise().minCoeff()).norm();
    const Eigen::Vector3d unit_normal = blade_.normal.normalized();
    side_.resize(nodes_.size());
    for (std::size_t n = 0; n < nodes_.size(); ++n) {
      side_[n] = blade_.side(nodes_[n]);
      if (side_[n] != 0 && std::abs((nodes_[n] - blade_.a).dot(unit_normal)) <= snap_distance) {
        side_[n] = 0;
        ++snapped_;
      }
    }
  }

  PolyhedralCut build() {
    classify_cells();
    for (int face = 0; face < mesh_.face_count(); ++face) split_face(face);
    for (int cell = 0; cell < mesh_.cell_count(); ++cell) {
      if (!crossed_[cell]) continue;
      if (!cap_covered_[cell]) {
        close_cap(cell, +1, piece(cell, -1));
        continue;
      }
      for (const int sigma : {+1, -1}) close_cap(cell, sigma, -1);
    }
    return assemble();
  }

private:
  // A face of the cut mesh before node duplication: its loop, the pieces on its two
  // sides (second −1 on the boundary), the side of the blade it lies on, and whether the
  // cut opened it (a boundary face that was inside the body).
  struct Face {
    std::vector<int> loop;
    int first, second, sigma;
    bool opened = false;
  };

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
      reached[cell] = positive && negative && in_piece_[cell];
      cell_sigma_[cell] = negative && !positive ? -1 : +1;
      if (reached[cell]) cap_covered_[cell] = covers_section(cell);
    }
    for (int face = 0; face < mesh_.face_count(); ++face)
      if (mesh_.face_cells(face, 1) >= 0 && has_both_sides(mesh_.faces[face]))
        joined.join(mesh_.face_cells(face, 0), mesh_.face_cells(face, 1));
    std::vector<bool> covered_group(cells, false);
    for (int cell = 0; cell < cells; ++cell)
      if (cap_covered_[cell]) covered_group[joined.find(cell)] = true;
    for (int cell = 0; cell < cells; ++cell) {
      first_piece_[cell] = static_cast<int>(parent_.size());
      parent_.push_back(cell);
      crossed_[cell] = reached[cell] && covered_group[joined.find(cell)];
      if (!crossed_[cell]) continue;
      if (!is_convex_cell(mesh_, cell, nodes_of(cell)))
        throw NumericalError("cut: the blade crosses cell " + std::to_string(cell) +
                             ", which is not convex (cutting non-convex cells is not implemented yet)");
      parent_.push_back(cell);
      ++crossed_count_;
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
  void add_cap_edges(int piece_index, const std::vector<int>& loop, bool closing_only) {
    const std::size_t n = loop.size();
    for (std::size_t k = 0; k < n; ++k) {
      const int from = loop[k], to = loop[(k + 1) % n];
      if (side_[from] != 0 || side_[to] != 0) continue;
      if (closing_only && k + 1 != n) continue;
      cap_edges_[piece_index].emplace(to, from);
    }
  }

  bool covers_face(const std::vector<int>& loop) const {
    return std::all_of(loop.begin(), loop.end(), [&](int node) { return blade_.covers(nodes_[node]); });
  }

  void add_face(std::vector<int> loop, int cell0, int cell1, int sigma, bool opened = false) {
    const int first = piece(cell0, sigma), second = piece(cell1, sigma);
    if (crossed_[cell0]) add_cap_edges(first, loop, false);
    if (cell1 >= 0 && crossed_[cell1]) {
      std::vector<int> reversed(loop.rbegin(), loop.rend());
      add_cap_edges(second, reversed, false);
    }
    faces_.push_back({std::move(loop), first, second, sigma, opened});
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
      if (cell1 >= 0 && in_piece_[cell0] && covers_face(loop)) {
        ++separated_;
        add_face(loop, cell0, -1, cell_sigma_[cell0], true);
        add_face(std::vector<int>(loop.rbegin(), loop.rend()), cell1, -1, cell_sigma_[cell1], true);
      } else {
        add_face(loop, cell0, cell1, cell_sigma_[cell0]);
      }
      return;
    }
    if (!(positive && negative) || !crossed_[cell0]) {
      add_face(loop, cell0, cell1, negative && !positive ? -1 : +1);
      return;
    }
    // Crossed: the loop with its crossing nodes, then the runs on either side of the
    // blade between its two nodes on the blade (a convex face has exactly two).
    std::vector<int> augmented;
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const int u = loop[k], v = loop[(k + 1) % loop.size()];
      augmented.push_back(u);
      if (side_[u] * side_[v] < 0) augmented.push_back(crossing_node(u, v));
    }
    std::vector<std::size_t> on_blade;
    for (std::size_t k = 0; k < augmented.size(); ++k)
      if (side_[augmented[k]] == 0) on_blade.push_back(k);
    if (on_blade.size() != 2)
      throw NumericalError("cut: the blade crosses face " + std::to_string(face) + " of cell " + std::to_string(cell0) +
                           " more than once (a non-convex face; cutting it is not implemented yet)");
    for (const auto& [start, end] : {std::pair{on_blade[0], on_blade[1]}, std::pair{on_blade[1], on_blade[0]}}) {
      std::vector<int> run;
      for (std::size_t k = start;; k = (k + 1) % augmented.size()) {
        run.push_back(augmented[k]);
        if (k == end) break;
      }
      const int sigma = side_[run[1]];
      // Only the closing edge (end → start) lies in the blade: the cap takes it reversed.
      const int first = piece(cell0, sigma), second = piece(cell1, sigma);
      add_cap_edges(first, run, true);
      if (second >= 0) cap_edges_[second].emplace(run.back(), run.front());
      faces_.push_back({std::move(run), first, second, sigma});
    }
  }

  // The cap of the piece of `cell` on side `sigma`: a boundary face when the blade covers
  // it, else the face joining that piece to `other_piece`.
  void close_cap(int cell, int sigma, int other_piece) {
    const int piece_index = piece(cell, sigma);
    std::map<int, int>& next = cap_edges_[piece_index];
    if (next.size() < 3)
      throw NumericalError("cut: the blade's section of cell " + std::to_string(cell) + " has fewer than 3 corners");
    std::vector<int> loop{next.begin()->first};
    while (loop.size() <= next.size()) {
      const auto found = next.find(loop.back());
      if (found == next.end()) break;
      if (found->second == loop.front()) break;
      loop.push_back(found->second);
    }
    if (loop.size() != next.size())
      throw NumericalError("cut: the blade's section of cell " + std::to_string(cell) + " is not one closed polygon");
    faces_.push_back({std::move(loop), piece_index, other_piece, sigma, other_piece < 0});
  }

  int piece_sigma(int piece_index) const {
    const int cell = parent_[piece_index];
    if (!crossed_[cell]) return cell_sigma_[cell];
    return piece_index == first_piece_[cell] ? +1 : -1;
  }

  // A node of a face the cut opened is held by pieces that may now lie apart: those joined
  // through the faces holding it that are not boundary faces form a group, and each group
  // but one gets a copy of the node — the group kept is the first with a piece on the
  // positive side, so a cut by the whole plane copies each node once, for the negative side.
  // At a finite blade's edge the pieces stay joined around the node: it is not copied.
  int duplicate_separated_nodes() {
    std::vector<bool> opened_node(nodes_.size(), false);
    std::vector<int> sides_using(nodes_.size(), 0);  // bit 1: positive, bit 2: negative
    for (const Face& face : faces_)
      for (const int node : face.loop) {
        opened_node[node] = opened_node[node] || face.opened;
        sides_using[node] |= face.sigma > 0 ? 1 : 2;
      }
    // Also a covered node that cells on both sides touch without a face in the plane (an
    // earlier cut's slivers left out make such meshes).
    for (std::size_t node = 0; node < nodes_.size(); ++node)
      if (sides_using[node] == 3 && !opened_node[node] && side_[node] == 0)
        opened_node[node] = blade_.covers(nodes_[node]) ||
                            (sources_[node].weight > 0 &&
                             blade_.covers_crossing(nodes_[sources_[node].first], nodes_[sources_[node].second]));
    std::vector<std::pair<int, int>> holders;  // (node, face)
    for (std::size_t f = 0; f < faces_.size(); ++f)
      for (const int node : faces_[f].loop)
        if (opened_node[node]) holders.emplace_back(node, static_cast<int>(f));
    std::sort(holders.begin(), holders.end());
    int duplicated = 0;
    std::vector<int> pieces, roots, copy_of_root;
    for (std::size_t begin = 0; begin < holders.size();) {
      const int node = holders[begin].first;
      std::size_t end = begin;
      while (end < holders.size() && holders[end].first == node) ++end;
      pieces.clear();
      for (std::size_t k = begin; k < end; ++k) {
        const Face& face = faces_[holders[k].second];
        pieces.push_back(face.first);
        if (face.second >= 0) pieces.push_back(face.second);
      }
      std::sort(pieces.begin(), pieces.end());
      pieces.erase(std::unique(pieces.begin(), pieces.end()), pieces.end());
      const auto local = [&](int piece_index) {
        return static_cast<int>(std::lower_bound(pieces.begin(), pieces.end(), piece_index) - pieces.begin());
      };
      DisjointSets groups(static_cast<int>(pieces.size()));
      for (std::size_t k = begin; k < end; ++k) {
        const Face& face = faces_[holders[k].second];
        if (face.second >= 0) groups.join(local(face.first), local(face.second));
      }
      roots.clear();
      for (int i = 0; i < static_cast<int>(pieces.size()); ++i)
        if (std::find(roots.begin(), roots.end(), groups.find(i)) == roots.end()) roots.push_back(groups.find(i));
      const auto kept = std::find_if(roots.begin(), roots.end(), [&](int root) {
        for (int i = 0; i < static_cast<int>(pieces.size()); ++i)
          if (groups.find(i) == root && piece_sigma(pieces[i]) > 0) return true;
        return false;
      });
      if (kept != roots.end()) std::rotate(roots.begin(), kept, kept + 1);
      copy_of_root.assign(pieces.size(), node);
      for (std::size_t r = 1; r < roots.size(); ++r) {
        copy_of_root[roots[r]] = static_cast<int>(nodes_.size());
        nodes_.push_back(nodes_[node]);
        sources_.push_back(sources_[node]);
        ++duplicated;
      }
      for (std::size_t k = begin; k < end; ++k) {
        Face& face = faces_[holders[k].second];
        const int copy = copy_of_root[groups.find(local(face.first))];
        if (copy != node) std::replace(face.loop.begin(), face.loop.end(), node, copy);
      }
      begin = end;
    }
    return duplicated;
  }

  PolyhedralCut assemble() {
    const int duplicated = duplicate_separated_nodes();
    PolyhedralCut cut;
    PolyhedralMesh& result = cut.mesh;
    result.nodes.resize(static_cast<Eigen::Index>(nodes_.size()), 3);
    for (std::size_t node = 0; node < nodes_.size(); ++node)
      result.nodes.row(static_cast<Eigen::Index>(node)) = nodes_[node];
    result.face_cells.resize(static_cast<Eigen::Index>(faces_.size()), 2);
    result.cell_faces.resize(parent_.size());
    for (std::size_t f = 0; f < faces_.size(); ++f) {
      Face& face = faces_[f];
      result.faces.push_back(std::move(face.loop));
      result.face_cells(static_cast<Eigen::Index>(f), 0) = face.first;
      result.face_cells(static_cast<Eigen::Index>(f), 1) = face.second;
      result.cell_faces[face.first].push_back(static_cast<int>(f));
      if (face.second >= 0) result.cell_faces[face.second].push_back(static_cast<int>(f));
    }
    for (std::size_t piece_index = 0; piece_index < parent_.size(); ++piece_index) {
      const int cell = parent_[piece_index];
      result.cell_kinds.push_back(crossed_[cell] ? PolyhedralCellKind::split : mesh_.cell_kinds[cell]);
    }
    if (compute_geometry_) compute_polyhedral_geometry(result);
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
  std::vector<bool> in_piece_;          ///< per input cell: the blade may cut it (piece_at)
  std::vector<Eigen::Vector3d> nodes_;  ///< the input's, then the crossing nodes, then the copies
  std::vector<NodeSource> sources_;     ///< per node of nodes_
  std::vector<int> side_;               ///< per node of nodes_ before the copies: −1, 0, +1
  std::vector<bool> crossed_;
  std::vector<bool> cap_covered_;  ///< per input cell the plane crosses: the blade covers its section
  std::map<std::pair<int, int>, bool> crossing_covered_;  ///< per edge the plane crosses
  std::vector<int> cell_sigma_;   ///< the side of an uncrossed cell (+1 when it has no node off the blade)
  std::vector<int> first_piece_;  ///< per input cell, its first piece
  std::vector<int> parent_;       ///< per piece, its input cell
  std::map<std::pair<int, int>, int> crossings_;
  std::vector<std::map<int, int>> cap_edges_;  ///< per piece: the cap's next node after each node
  std::vector<Face> faces_;
  int crossed_count_ = 0, joined_count_ = 0, separated_ = 0, snapped_ = 0;
  bool compute_geometry_ = true;
};

}  // namespace

PolyhedralCut cut_polyhedral_mesh(const PolyhedralMesh& mesh, const CuttingPlane& plane, bool compute_geometry) {
  return CutBuilder(mesh, plane, compute_geometry).build();
}

}  // namespace altfem
