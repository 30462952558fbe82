#pragma once
// The builder of cut_polyhedral_mesh (its two files: cut_polyhedral_mesh.cpp decides which
// cells the blade crosses and where it crosses their edges, cut_polyhedral_faces.cpp
// splits their faces, closes their caps and assembles the cut mesh). Only those include it.
#include <Eigen/Core>
#include <array>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "shared/common/error.hpp"
#include "shared/mesh/convex_cell.hpp"
#include "shared/mesh/cut_polyhedral_mesh.hpp"
#include "shared/mesh/cut_polyhedral_pieces.hpp"
#include "shared/mesh/planar_loops.hpp"

namespace altfem::polyhedral_cut {

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
        scope.snap_fraction * (scope.snap_length > 0
                                   ? scope.snap_length
                                   : (mesh.nodes.colwise().maxCoeff() - mesh.nodes.colwise().minCoeff()).norm());
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
  bool covers_section(int cell);

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
  void add_crossings_to_whole_faces();

  // Per cell, whether the blade may cut it: every cell, or with `piece_at` the cells
  // connected through faces to one holding the node nearest that point.
  std::vector<bool> cells_of_piece_at() const;

  // A cell with nodes on both sides is crossed when the blade covers its section or that
  // of a cell joined to it through faces the plane crosses: a face the plane crosses is
  // split for both of its cells, so the mesh stays conforming. A crossed cell whose section
  // the blade does not cover keeps its two pieces joined (a finite blade's edge runs
  // through it, or it lies beyond the edge): the cut ends at the last cell it covers.
  void classify_cells();

  // The piece of `cell` on side `sigma`: a crossed cell has two (positive first).
  int piece(int cell, int sigma) const {
    if (cell < 0) return -1;
    return first_piece_[cell] + (crossed_[cell] && sigma < 0 ? 1 : 0);
  }

  // The node where the blade crosses edge (u, v), whose ends lie strictly on either side:
  // one per edge, shared by every face that holds it.
  int crossing_node(int u, int v);

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

  void split_face(int face);

  // The caps of the pieces of `cell` on side `sigma`: the polygons their blade edges close
  // (several where a non-convex cell's section falls apart; an edge that two of its faces
  // hold both ways — where a face of it lies in the blade's plane — bounds none). Each is a
  // boundary face when the blade covers the section, else a face joining the pieces on the
  // two sides.
  void close_caps(int cell, int sigma, bool joined);

  // The split cells without a section stay whole: each one's negative half's faces go to
  // its positive half, and the pieces after it move down.
  void rejoin_halves(const std::vector<int>& cells);

  // The nodes a copy of which each group of pieces apart around it needs: those of faces
  // the cut opened, and a covered node that cells on both sides touch without a face in
  // the plane (an earlier cut's slivers left out make such meshes).
  std::vector<bool> opened_nodes() const;

  PolyhedralCut assemble();

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

}  // namespace altfem::polyhedral_cut
