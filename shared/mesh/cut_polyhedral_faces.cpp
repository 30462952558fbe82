#include <algorithm>
#include <string>

#include "shared/mesh/cut_polyhedral_builder.hpp"
#include "shared/mesh/split_holes.hpp"

namespace altfem::polyhedral_cut {

void CutBuilder::add_crossings_to_whole_faces() {
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

void CutBuilder::split_face(int face) {
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

void CutBuilder::close_caps(int cell, int sigma, bool joined) {
  const int piece_index = piece(cell, sigma);
  std::vector<std::pair<int, int>> edges = std::move(cap_edges_[piece_index]);
  std::sort(edges.begin(), edges.end());
  std::vector<bool> cancelled(edges.size(), false);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (cancelled[e]) continue;
    const auto [begin, end] = std::equal_range(edges.begin(), edges.end(), std::pair{edges[e].second, edges[e].first});
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

void CutBuilder::rejoin_halves(const std::vector<int>& cells) {
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

std::vector<bool> CutBuilder::opened_nodes() const {
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

PolyhedralCut CutBuilder::assemble() {
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

}  // namespace altfem::polyhedral_cut
